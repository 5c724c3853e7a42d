#include "tools/lsys/render_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/image/image.h"
#include "engine/scene/camera.h"
#include "lsystem/common/error.h"
#include "lsystem/components/component_graph.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/raytrace/flat_tracer.h"
#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/raytrace/lazy_graph_tracer.h"
#include "lsystem/raytrace/render.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "tools/lsys/output_check.h"
#include "tools/lsys/plant_loading.h"

namespace tools {

namespace {

// --size: past 16384 pixels a side the image alone is a gigabyte.
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint32_t kMaxSamples = 256;
// --cache-budget's default: the expansions of the plants in data/ take
// kilobytes (docs/RAYTRACING.md, "Lazy expansion"), so this holds all of a
// plant's unless its single objects are large, and is a small share of the
// memory of a machine that renders.
constexpr uint64_t kDefaultCacheBudget = uint64_t{256} << 20;

// How many times the plant's size --camera may be from its box: float rays
// from there still place a hit within a hundredth of the plant's size (a
// float's 6e-8 of the distance), and farther out the plant is under a pixel
// at any --size and a field of view above a few degrees.
constexpr double kMaxCameraDistanceInSizes = 1e5;

enum class TracerKind { Graph, Flat, Lazy };

struct RenderArguments : DerivationArguments {
    std::string output;
    uint32_t width = 1280, height = 720;
    std::optional<lsys::PinholeCamera> camera; // --camera; else framed from --view
    lsys::ViewAngles view;
    pf::Environment environment; // the renderer's sun and sky, --sun turning the sun
    TracerKind tracer = TracerKind::Graph;
    uint64_t maxFlatPrimitives = 10'000'000;
    std::optional<uint64_t> cacheBudget; // --cache-budget, --tracer lazy only
    uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
    uint32_t samples = 1;
    bool shadows = true;
    bool ground = true;
};

// Comma-separated finite numbers: `count` or `orCount` of them.
std::optional<std::vector<float>> parseNumbers(const std::string& text, size_t count, size_t orCount) {
    std::vector<float> numbers;
    const char* at = text.c_str();
    while (true) {
        char* end = nullptr;
        const float value = std::strtof(at, &end);
        if (end == at || !std::isfinite(value)) return std::nullopt;
        numbers.push_back(value);
        if (*end == '\0') break;
        if (*end != ',') return std::nullopt;
        at = end + 1;
    }
    if (numbers.size() != count && numbers.size() != orCount) return std::nullopt;
    return numbers;
}

// "WxH" with both sides in [1, kMaxImageSide].
std::optional<std::pair<uint32_t, uint32_t>> parseSize(const std::string& text) {
    char* end = nullptr;
    const unsigned long width = std::strtoul(text.c_str(), &end, 10);
    if (end == text.c_str() || (*end != 'x' && *end != 'X') || !std::isdigit(static_cast<unsigned char>(end[1])))
        return std::nullopt;
    const char* heightText = end + 1;
    const unsigned long height = std::strtoul(heightText, &end, 10);
    if (*end != '\0' || width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) return std::nullopt;
    return std::pair{uint32_t(width), uint32_t(height)};
}

std::optional<lsys::PinholeCamera> parseCamera(const std::string& text) {
    const std::optional<std::vector<float>> n = parseNumbers(text, 6, 7);
    if (!n) return std::nullopt;
    lsys::PinholeCamera camera{{(*n)[0], (*n)[1], (*n)[2]}, {(*n)[3], (*n)[4], (*n)[5]}};
    if (n->size() == 7) camera.fovYDegrees = (*n)[6];
    if (camera.target == camera.position || !(camera.fovYDegrees > 0.0f && camera.fovYDegrees < 180.0f))
        return std::nullopt;
    return camera;
}

// Azimuth and elevation in degrees, the elevation strictly between -90 and 90.
std::optional<std::pair<float, float>> parseAngles(const std::string& text) {
    const std::optional<std::vector<float>> n = parseNumbers(text, 2, 2);
    if (!n || !((*n)[1] > -90.0f && (*n)[1] < 90.0f)) return std::nullopt;
    return std::pair{(*n)[0], (*n)[1]};
}

// The option's check: an empty string when `parse` accepts the text, else `problem`.
template <typename Parse>
CLI::Validator accepting(Parse parse, std::string problem) {
    return CLI::Validator(
        [parse, problem](std::string& text) { return parse(text) ? std::string() : "'" + text + "' " + problem; }, "");
}

std::string formatAngles(float azimuth, float elevation) {
    std::ostringstream text;
    text << azimuth << ',' << elevation;
    return text.str();
}

lsys::Lighting lightingOf(const pf::Environment& environment) {
    return {pf::sunDirection(environment), environment.sunRadiance, environment.skyZenith, environment.skyHorizon,
            environment.groundAlbedo};
}

// Prints how far a long render is, every few seconds.
std::function<void(uint32_t)> progressPrinter(uint32_t rows) {
    constexpr auto kInterval = std::chrono::seconds(5);
    auto last = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
    return [rows, last, kInterval](uint32_t done) {
        const auto now = std::chrono::steady_clock::now();
        if (now - *last < kInterval || done == rows) return;
        *last = now;
        std::cerr << "lsys render: " << 100 * uint64_t(done) / rows << "% of the rows\n";
    };
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The distance from `point` to the box, in double: a --camera 10^20 away
// squares past float's range.
double distanceToBox(const glm::vec3& point, const lsys::Bounds& bounds) {
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double outside =
            std::max({double(bounds.min[axis]) - point[axis], double(point[axis]) - bounds.max[axis], 0.0});
        squared += outside * outside;
    }
    return std::sqrt(squared);
}

// An empty string when --camera (if any) is near enough to the plant's box
// for its rays to resolve the plant, else why not.
std::string cameraDistanceProblem(const RenderArguments& arguments, const lsys::Bounds& bounds) {
    if (!arguments.camera) return {};
    const double size = glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
    const double distance = distanceToBox(arguments.camera->position, bounds);
    if (distance <= kMaxCameraDistanceInSizes * size) return {};
    std::ostringstream text;
    text << "--camera is " << distance << " from the plant's box, more than " << kMaxCameraDistanceInSizes
         << " times the plant's size (" << size << "): float rays cannot resolve the plant from there";
    return text.str();
}

// Traces the image through `trace` and writes it; prints the rays, their
// rate, and the time since `begun` (the plant read, its graph and tracer built).
int renderAndWrite(const RenderArguments& arguments, const lsys::PlantTrace& trace,
                   const std::vector<lsys::Material>& materials, const lsys::Bounds& bounds, const char* tracerName,
                   std::chrono::steady_clock::time_point begun) {
    if (const std::string problem = cameraDistanceProblem(arguments, bounds); !problem.empty()) {
        std::cerr << "lsys: error: " << problem << '\n';
        return kBadInput;
    }
    lsys::RenderOptions options;
    options.width = arguments.width;
    options.height = arguments.height;
    options.camera = arguments.camera.value_or(
        lsys::framedCamera(bounds, float(options.width) / float(options.height), arguments.view));
    options.light = lightingOf(arguments.environment);
    options.shadows = arguments.shadows;
    // The plant's base: the turtle starts at the origin, which a plant drawn downwards lies below.
    if (arguments.ground) options.groundHeight = std::min(0.0f, bounds.min.y);
    options.samples = arguments.samples;
    options.threads = arguments.threads;
    options.onRow = progressPrinter(options.height);
    const auto start = std::chrono::steady_clock::now();
    const lsys::RenderedImage image = renderImage(trace, materials, glm::length(bounds.max - bounds.min), options);
    const double seconds = secondsSince(start);
    try {
        pf::writePng(arguments.output, {image.width, image.height, image.rgba});
    } catch (const std::runtime_error& error) {
        std::cerr << "lsys: error: " << error.what() << '\n';
        return kBadInput;
    }
    const uint64_t rays = image.cameraRays + image.shadowRays;
    std::cerr << arguments.output << ": " << image.width << "x" << image.height << ", " << tracerName << " tracer, "
              << image.cameraRays << " camera and " << image.shadowRays << " shadow rays in " << seconds << " s ("
              << uint64_t(double(rays) / std::max(seconds, 1e-9)) << " rays/s on " << arguments.threads
              << (arguments.threads == 1 ? " thread), " : " threads), ") << secondsSince(begun) << " s in all\n";
    return 0;
}

// The plant flattened and traced through one BVH, when it fits the budgets.
int renderFlat(const RenderArguments& arguments, const lsys::InstanceGraph& graph, const lsys::SurfaceLibrary& surfaces,
               const lsys::Bounds& bounds, std::chrono::steady_clock::time_point begun) {
    const uint64_t primitives = lsys::instanceGraphStats(graph).primitives;
    if (primitives > arguments.maxFlatPrimitives) {
        std::cerr << arguments.file << ": error: --tracer flat: the plant has " << primitives
                  << " primitives, more than the flat tracer's budget of " << arguments.maxFlatPrimitives
                  << " (--max-flat-primitives sets it; --tracer graph traces the plant without flattening it)\n";
        return kBadInput;
    }
    // The flat plant's primitives and joints, and per primitive the tracer's box, BVH item and (at most) node.
    const uint64_t perPrimitive =
        sizeof(lsys::Primitive) + sizeof(lsys::Joint) + sizeof(lsys::Bounds) + sizeof(uint32_t) + sizeof(lsys::BvhNode);
    lsys::need(arguments.memory, "flat tracer", lsys::bytesTimes(primitives, perPrimitive));
    const lsys::PlantAsset plant = lsys::flatten(graph, surfaces, arguments.maxFlatPrimitives);
    const lsys::FlatTracer tracer = lsys::buildFlatTracer(plant);
    return renderAndWrite(arguments, lsys::traceOf(tracer), plant.materials, bounds, "flat", begun);
}

// The lazy tracer's budget: --cache-budget, else the default within the memory budget.
uint64_t cacheBudgetOf(const RenderArguments& arguments) {
    if (!arguments.cacheBudget) return std::min(kDefaultCacheBudget, arguments.memory.limitBytes);
    lsys::need(arguments.memory, "expansion cache (--cache-budget)", *arguments.cacheBudget);
    return *arguments.cacheBudget;
}

// The plant traced without building its whole graph: objects expanded from
// the b-grammar as rays reach them, held under --cache-budget (Robbins 1998,
// §3). Framed on the lazy tracer's box of the root, which places the
// children's boxes rather than their descendants' and so can be wider than
// the graph tracer's: the same --camera gives the graph tracer's image.
int renderLazy(const RenderArguments& arguments, const lsys::BGrammar& bgrammar, const lsys::Grammar& grammar,
               const lsys::InstanceGraphOptions& graphOptions, const lsys::SurfaceLibrary& surfaces,
               std::chrono::steady_clock::time_point begun) {
    const uint64_t budget = cacheBudgetOf(arguments);
    const lsys::LazyInstanceGraph graph = lsys::deriveLazyInstanceGraph(bgrammar, grammar, graphOptions, surfaces);
    const lsys::LazyGraphTracer tracer = lsys::buildLazyGraphTracer(graph, budget, surfaces);
    const lsys::Bounds bounds = graph.graph.objects.empty() ? lsys::Bounds{} : tracer.objectBounds[graph.graph.root];
    if (bounds.empty()) {
        std::cerr << arguments.file << ": error: the plant draws nothing to render\n";
        return kBadInput;
    }
    const int status =
        renderAndWrite(arguments, lsys::traceOf(tracer), lsys::materialsOf(graph), bounds, "lazy", begun);
    const lsys::ExpansionStats stats = lsys::expansionStats(tracer);
    if (status == 0)
        std::cerr << "lazy tracer: " << graph.graph.objects.size() << " objects, " << stats.expansions
                  << " expansions, " << stats.evictions << " evictions, at most " << lsys::formatBytes(stats.peakBytes)
                  << " held of a " << lsys::formatBytes(budget) << " cache budget\n";
    return status;
}

int runRender(const RenderArguments& arguments) {
    const auto begun = std::chrono::steady_clock::now();
    if (arguments.cacheBudget && arguments.tracer != TracerKind::Lazy) {
        std::cerr << "lsys: error: --cache-budget sizes the lazy tracer's expansion cache; it needs --tracer lazy\n";
        return kBadInput;
    }
    if (lsys::components::isComponentFile(arguments.file) || lsys::isRamificationFile(arguments.file)) {
        std::cerr << "lsys: error: render traces an L-system's InstanceGraph; a component plant or ramification "
                     "tree has none (lsys export writes it as a mesh)\n";
        return kBadInput;
    }
    const std::filesystem::path output[] = {arguments.output};
    if (outputRefused(output, arguments.file)) return kBadInput;
    const std::optional<lsys::Grammar> grammar = loadGrammar(arguments);
    // Again now that its includes and a vlab object's files are read.
    if (!grammar || outputRefused(output, arguments.file)) return kBadInput;
    const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(arguments.file));
    try {
        lsys::need(arguments.memory, "image", lsys::bytesTimes(uint64_t(arguments.width) * arguments.height, 4));
        lsys::InstanceGraphOptions graphOptions;
        graphOptions.memory = arguments.memory;
        const lsys::BGrammar bgrammar = lsys::buildBGrammar(*grammar, bgrammarOptions(arguments));
        if (arguments.tracer == TracerKind::Lazy)
            return renderLazy(arguments, bgrammar, *grammar, graphOptions, surfaces, begun);
        const lsys::InstanceGraph graph = lsys::buildInstanceGraph(bgrammar, *grammar, graphOptions, surfaces);
        // The graph and flat tracers' images are framed on the graph tracer's
        // box, so the two compare pixel for pixel. Built from the objects' descendants, it is
        // within 1 % of the flattened plant's for the 6-step fractal bush, where
        // GraphObject::bounds, boxes of placed boxes, is 40 % wider.
        const lsys::GraphTracer tracer = lsys::buildGraphTracer(graph, surfaces);
        const lsys::Bounds bounds = graph.objects.empty() ? lsys::Bounds{} : tracer.objectBounds[graph.root];
        if (bounds.empty()) {
            std::cerr << arguments.file << ": error: the plant draws nothing to render\n";
            return kBadInput;
        }
        if (arguments.tracer == TracerKind::Flat) return renderFlat(arguments, graph, surfaces, bounds, begun);
        return renderAndWrite(arguments, lsys::traceOf(tracer), lsys::materialsOf(graph), bounds, "graph", begun);
    } catch (const std::runtime_error& error) { // DerivationError, MemoryBudgetError, SurfaceError
        std::cerr << arguments.file << ": error: " << error.what() << '\n';
        return kBadInput;
    }
}

void addOptions(CLI::App& command, RenderArguments& arguments) {
    addDerivationOptions(command, arguments);
    command.add_option("-o,--output", arguments.output, "The image: a PNG file")->required();
    command
        .add_option_function<std::string>(
            "--size",
            [&arguments](const std::string& text) { std::tie(arguments.width, arguments.height) = *parseSize(text); },
            "Image size in pixels (default 1280x720)")
        ->type_name("WxH")
        ->check(accepting(parseSize, "is not a size: expected WIDTHxHEIGHT, each 1 to 16384, e.g. 1280x720"));
    command
        .add_option_function<std::string>(
            "--camera", [&arguments](const std::string& text) { arguments.camera = parseCamera(text); },
            "Camera position and target in plant space, and the vertical field of view in degrees (default 45); "
            "looking straight down, +x is right and -z up in the image; default: framed from --view around the "
            "plant's box")
        ->type_name("EX,EY,EZ,TX,TY,TZ[,FOV]")
        ->check(accepting(parseCamera, "is not a camera: expected 6 or 7 numbers, the target not the position, the "
                                       "field of view between 0 and 180 degrees"));
    command
        .add_option_function<std::string>(
            "--view",
            [&arguments](const std::string& text) {
                std::tie(arguments.view.azimuthDegrees, arguments.view.elevationDegrees) = *parseAngles(text);
            },
            "Where the framed camera looks from: degrees clockwise from -z towards +x, and above the horizon "
            "(default " +
                formatAngles(arguments.view.azimuthDegrees, arguments.view.elevationDegrees) + ")")
        ->type_name("AZ,EL")
        ->check(accepting(parseAngles, "is not AZ,EL: two numbers in degrees, the elevation between -90 and 90"));
    command
        .add_option_function<std::string>(
            "--sun",
            [&arguments](const std::string& text) {
                std::tie(arguments.environment.sunAzimuthDegrees, arguments.environment.sunElevationDegrees) =
                    *parseAngles(text);
            },
            "Sun azimuth (clockwise from -z towards +x) and elevation in degrees (default: plantfield's, " +
                formatAngles(arguments.environment.sunAzimuthDegrees, arguments.environment.sunElevationDegrees) + ")")
        ->type_name("AZ,EL")
        ->check(accepting(parseAngles, "is not AZ,EL: two numbers in degrees, the elevation between -90 and 90"));
    command
        .add_option_function<std::string>(
            "--tracer",
            [&arguments](const std::string& name) {
                arguments.tracer = name == "flat"   ? TracerKind::Flat
                                   : name == "lazy" ? TracerKind::Lazy
                                                    : TracerKind::Graph;
            },
            "graph (default: through the InstanceGraph, every object stored once), flat (the flattened plant in "
            "one BVH, within --max-flat-primitives) or lazy (each object expanded from the b-grammar when a ray "
            "reaches it, held within --cache-budget; framed on its own, possibly wider, box)")
        ->check(CLI::IsMember({"graph", "flat", "lazy"}))
        ->type_name("graph|flat|lazy");
    command
        .add_option("--max-flat-primitives", arguments.maxFlatPrimitives,
                    "The most primitives --tracer flat flattens (default 10000000)")
        ->check(CLI::PositiveNumber);
    command
        .add_option_function<std::string>(
            "--cache-budget",
            [&arguments](const std::string& text) { arguments.cacheBudget = lsys::parseByteSize(text); },
            "With --tracer lazy only: the most the expanded objects may hold, e.g. 64M, 1G or bytes; past it the "
            "least recently used are dropped and expanded again when a ray needs them (default " +
                lsys::formatBytes(kDefaultCacheBudget) + ", at most the memory budget)")
        ->type_name("SIZE")
        ->check(
            accepting(lsys::parseByteSize, "is not a size: expected bytes or a number with K, M, G or T, e.g. 64M"));
    command
        .add_option("--threads", arguments.threads,
                    "Threads tracing rows (default: every core, " + std::to_string(arguments.threads) +
                        "); the image is the same for any count")
        ->check(CLI::Range(1, 1024));
    command.add_option("--samples", arguments.samples, "Rays per pixel, spread over it (default 1: its centre)")
        ->check(CLI::Range(1u, kMaxSamples));
    command.add_flag("!--no-shadows", arguments.shadows, "Light every surface facing the sun, tracing no shadow rays");
    command.add_flag("!--no-ground", arguments.ground, "Sky below the horizon instead of a ground plane at the base");
    command.add_option("--max-modules", arguments.maxModules, "Module budget when the word must be derived first")
        ->check(CLI::PositiveNumber);
}

} // namespace

Command addRenderCommand(CLI::App& app) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* command = app.add_subcommand(
        "render", "Ray trace one plant on the CPU into a PNG (docs/RAYTRACING.md): its InstanceGraph traced without "
                  "flattening (or expanded lazily, --tracer lazy), lit by plantfield's sun with ray-traced shadows and "
                  "its sky, on a ground plane, framed from "
                  "its box. Prints the rays traced and their rate");
    addOptions(*command, *arguments);
    return {command, [arguments] { return runRender(*arguments); }};
}

} // namespace tools
