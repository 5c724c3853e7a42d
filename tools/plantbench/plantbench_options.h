// Command-line options of plantbench, parsed and checked before any GPU work.
#pragma once

#include "tools/field_options.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pf {

// "1000,10000" → {1000, 10000}; nullopt when empty, malformed, zero, or a
// count above `maxCount`. `problem` says which.
std::optional<std::vector<uint64_t>> parseCounts(const std::string& text, uint64_t maxCount, std::string* problem);

// `--path` without a value: times along the camera path.
inline constexpr uint32_t kDefaultPathTimes = 8;
inline constexpr uint32_t kMaxPathTimes = 1000;

// The K of "--path K": a whole number 1 to kMaxPathTimes; an empty text is
// kDefaultPathTimes. nullopt for anything else, `problem` says why.
std::optional<uint32_t> parsePathTimes(const std::string& text, std::string* problem);

// Besides the options both field tools take (tools/field_options.h).
struct PlantbenchOptions : FieldToolOptions {
    std::vector<uint64_t> counts;      // plants per sweep step, in the order given
    uint32_t frames = 10;              // measured frames per count (and per path)
    uint32_t warmup = 2;               // frames rendered first and not measured
    std::optional<uint32_t> pathTimes; // --path: measure at this many times along the camera path instead
    // --fly: the camera follows its path through the measured frames, this
    // many frames a scene second, as in a window; otherwise it stays.
    std::optional<double> flyFps;
    bool densify = false; // counts on the scene's terrain, distances scaled (not natural densities)
    bool compareNaive = false;
    uint64_t naiveMax = 100000; // counts above this skip the naive path
    std::string jsonPath, csvPath, plotPath;
};

// Parses argv. On --help prints usage and sets *exitCode to 0; on a bad flag
// prints a clear error and sets *exitCode to 2. Returns nullopt whenever the
// program should exit with *exitCode.
std::optional<PlantbenchOptions> parsePlantbenchOptions(int argc, char** argv, int* exitCode);

// "cannot write --json file: REASON" for the first of --json, --csv and
// --plot that cannot be written or is a file the run reads (the scene, and
// every file the thread's ReadFileLogs recorded: the output rule of
// lsystem/common/output_file.h); empty when none. Checked while parsing and
// again once the field is built, before it is measured.
std::string outputsProblem(const PlantbenchOptions& o);

} // namespace pf
