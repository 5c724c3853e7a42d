// The command-line options plantfield and plantbench both take, declared
// once: the scene, the frame's size and time, anti-aliasing, the sun's
// shadows, occlusion culling, clusters, the seed, the device, validation and
// the memory budget; and the parsing both tools share (exit code 0 after
// --help, 2 with a clear message on a bad flag).
#pragma once

#include "engine/field/sun_shadows.h"
#include "engine/scene/scene.h"
#include "engine/vk/antialiasing.h"
#include "lsystem/common/memory_budget.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace pf {

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

// "1280x720" → {1280, 720}; nullopt for anything else, zero, or > 16384.
std::optional<ImageSize> parseImageSize(const std::string& text);

// The whole of `text` as a finite number of type T, or nullopt (from_chars
// takes "nan" and "inf", and parses a prefix; a float out of range fails).
template <class T>
std::optional<T> finiteNumber(std::string_view text) {
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// Accepts only finite numbers from min to max (both included). CLI11's
// Range and NonNegativeNumber compare with < and >, which NaN passes, and
// infinity passes an open upper end.
void checkFiniteIn(CLI::Option& option, double min, double max);

// The scene a tool renders when none is named: scenes/default.json of the
// data folder (tools/data_dir.h: PLANTFIELD_DATA_DIR, an installed tree's
// share/plantfield/data, or the source tree's data/).
std::string defaultScenePath();

// The environment both tools read, for their --help's footer.
inline constexpr const char* kFieldToolEnvironment =
    "Environment: PLANTFIELD_DEVICE picks the device by name, PLANTFIELD_VALIDATION=1 turns on\n"
    "the Khronos validation layer, PLANTFIELD_DATA_DIR replaces the data folder.";

// What the shared options set. Each tool's options extend it.
struct FieldToolOptions {
    std::string scenePath;
    ImageSize size{1280, 720};
    double time = 0.0; // scene seconds: of the (first) frame, or of the camera on its path
    Antialiasing antialiasing;
    SunShadows shadows = SunShadows::map;
    bool occlusionCulling = false; // --occlusion: plants behind the depth pyramid are not drawn
    bool clusters = true;          // false: every plant through the per-plant cull, no far canopy (--no-clusters)
    std::optional<uint32_t> seed;  // replaces the scene's seed
    std::string deviceName;
    bool validation = false;
    lsys::MemoryBudget memory; // --memory-budget: every stage building the field
};

// The shared options' texts that are checked after CLI11 has parsed them:
// the size, and --aa with --samples (the sample count only with msaa).
struct FieldToolTexts {
    std::string size = "1280x720";
    std::string antialiasMethod = antialiasMethodName(AntialiasMethod::fxaa);
    std::optional<uint32_t> samples;
};

// Declares the shared options on `app`, their values into `options` and
// `texts`, which must outlive the parse; defaults from the machine and the
// build (validation, the memory budget, the default scene).
void addFieldToolOptions(CLI::App& app, FieldToolOptions& options, FieldToolTexts& texts);

// After the parse: the size and the anti-aliasing from their texts. An empty
// string, or what is wrong with them.
std::string finishFieldToolOptions(const FieldToolTexts& texts, FieldToolOptions& options);

// Parses argv into `app`. --help and --version print and set *exitCode to 0;
// a bad flag prints "PROGRAM: error: …" with a pointer to --help and sets it
// to 2. False whenever the program should exit with *exitCode.
bool parseToolCommandLine(CLI::App& app, int argc, char** argv, const char* program, int* exitCode);

// Prints "PROGRAM: error: MESSAGE" and sets *exitCode to 2 (bad input).
void reportBadOption(const char* program, const std::string& message, int* exitCode);

// An output file as its flag names it: {"--capture", &o.capturePath}.
struct FlaggedOutput {
    const char* flag;
    const std::string* path; // empty: not asked for
};

// "cannot write FLAG file: REASON" for the first output the output rule
// (lsystem/common/output_file.h) refuses against `input` and the files the
// run has read; empty when every one may be written.
std::string flaggedOutputsProblem(std::initializer_list<FlaggedOutput> outputs, const std::filesystem::path& input);

} // namespace pf
