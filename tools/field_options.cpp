#include "tools/field_options.h"

#include "engine/vk/device.h"
#include "lsystem/common/output_file.h"
#include "tools/data_dir.h"
#include "tools/memory_budget_option.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace pf {
namespace {

constexpr uint32_t kMaxImageSide = 16384;

bool parseSide(const char* first, const char* last, uint32_t& out) {
    auto [end, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && end == last && out > 0 && out <= kMaxImageSide;
}

} // namespace

std::optional<ImageSize> parseImageSize(const std::string& text) {
    const size_t x = text.find('x');
    if (x == std::string::npos || x == 0 || x + 1 == text.size()) return std::nullopt;
    ImageSize size;
    const char* s = text.data();
    if (!parseSide(s, s + x, size.width) || !parseSide(s + x + 1, s + text.size(), size.height)) return std::nullopt;
    return size;
}

void checkFiniteIn(CLI::Option& option, double min, double max) {
    option.check(
        [min, max](const std::string& text) -> std::string {
            const std::optional<double> number = finiteNumber<double>(text);
            if (!number) return "'" + text + "' is not a finite number";
            const double value = *number;
            if (value < min || value > max)
                return "'" + text + "' is outside " + CLI::detail::to_string(min) + " to " +
                       CLI::detail::to_string(max);
            return {};
        },
        "FINITE");
}

std::string defaultScenePath() { return dataDirectory() + "/scenes/default.json"; }

void addFieldToolOptions(CLI::App& app, FieldToolOptions& o, FieldToolTexts& texts) {
    o.validation = validationWantedByDefault();
    o.scenePath = defaultScenePath();
    app.add_option("scene", o.scenePath, "Scene file (.json)")->default_str("data/scenes/default.json");
    app.add_option("--size", texts.size, "Frame (or window) size as WIDTHxHEIGHT (1 to 16384 per side)")
        ->default_str(texts.size);
    checkFiniteIn(*app.add_option("--time", o.time,
                                  "Scene time in seconds (of the first frame, and where the camera is on its path)"),
                  0.0, kMaxSceneTime);
    const CLI::Validator method(
        [](std::string& name) { return antialiasMethodNamed(name) ? "" : "expected fxaa, msaa or none"; },
        "fxaa|msaa|none");
    app.add_option("--aa", texts.antialiasMethod,
                   "Anti-aliasing: fxaa (one sample a pixel, then an FXAA pass), msaa (--samples a pixel,\n"
                   "resolved) or none")
        ->check(method)
        ->default_str(texts.antialiasMethod);
    app.add_option("--samples", texts.samples,
                   "With --aa msaa: samples a pixel, 2, 4 or 8 (default 4; lowered to what the device supports)")
        ->check(CLI::IsMember({2, 4, 8}));
    SunShadows& shadows = o.shadows;
    app.add_option_function<std::string>(
           "--shadows", [&shadows](const std::string& name) { shadows = *sunShadowsNamed(name); },
           "The sun's shadows: map (a shadow map over the field near the camera), raytraced (a ray a pixel\n"
           "to the sun through the field's plants, docs/RAYTRACING.md) or none (default map)")
        ->check(CLI::IsMember({"map", "raytraced", "none"}))
        ->type_name("map|raytraced|none");
    app.add_flag_callback(
        "--no-shadows", [&shadows] { shadows = SunShadows::none; }, "No sun shadows (--shadows none)");
    app.add_flag("--occlusion", o.occlusionCulling,
                 "Occlusion culling: do not draw the plants behind the depth pyramid of what the previous\n"
                 "frame's visible plants and the terrain cover (docs/CULLING.md; off by default: on a CPU\n"
                 "rasteriser it costs more than it saves)");
    app.add_flag("!--no-clusters", o.clusters,
                 "Send every plant through the per-plant cull every frame: no quadtree of clusters, no far canopy\n"
                 "(docs/CLUSTERS.md)");
    app.add_option("--seed", o.seed, "Replace the scene's seed (terrain, plants and placement change)");
    app.add_option("--device", o.deviceName, "Use the Vulkan device whose name contains this text");
    app.add_flag("--validation,!--no-validation", o.validation,
                 "Enable the Khronos validation layer (default: on in debug builds)");
    tools::addMemoryBudgetOption(app, o.memory);
}

std::string finishFieldToolOptions(const FieldToolTexts& texts, FieldToolOptions& o) {
    const std::optional<ImageSize> size = parseImageSize(texts.size);
    if (!size)
        return "invalid --size '" + texts.size + "': expected WIDTHxHEIGHT with each side 1 to 16384, e.g. 1280x720";
    o.size = *size;
    o.antialiasing.method = *antialiasMethodNamed(texts.antialiasMethod);
    if (texts.samples && o.antialiasing.method != AntialiasMethod::msaa)
        return "--samples is the MSAA sample count: it needs --aa msaa (anti-aliasing is --aa " +
               texts.antialiasMethod + ")";
    o.antialiasing.msaaSamples = texts.samples.value_or(o.antialiasing.msaaSamples);
    return {};
}

bool parseToolCommandLine(CLI::App& app, int argc, char** argv, const char* program, int* exitCode) {
    try {
        app.parse(argc, argv);
        return true;
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            *exitCode = app.exit(e);
            return false;
        }
        std::cerr << program << ": error: " << e.what() << "\nRun '" << program << " --help' for usage.\n";
        *exitCode = 2;
        return false;
    }
}

void reportBadOption(const char* program, const std::string& message, int* exitCode) {
    std::cerr << program << ": error: " << message << "\n";
    *exitCode = 2;
}

std::string flaggedOutputsProblem(std::initializer_list<FlaggedOutput> outputs, const std::filesystem::path& input) {
    for (const FlaggedOutput& output : outputs) {
        if (output.path->empty()) continue;
        if (const std::string problem = lsys::outputPathProblem(*output.path, {&input, 1}); !problem.empty())
            return std::string("cannot write ") + output.flag + " file: " + problem;
    }
    return {};
}

} // namespace pf
