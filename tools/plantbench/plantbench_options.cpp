#include "plantbench_options.h"

#include "shaders/shared/field_layouts.h"
#include "tools/field_options.h"

#include <CLI/CLI.hpp>
#include <plantfield_version.h>

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace pf {

std::optional<std::vector<uint64_t>> parseCounts(const std::string& text, uint64_t maxCount, std::string* problem) {
    if (text.empty()) {
        *problem = "expected a comma-separated list of plant counts, e.g. 1000,10000";
        return std::nullopt;
    }
    std::vector<uint64_t> counts;
    size_t start = 0;
    while (true) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        uint64_t count = 0;
        auto [end, ec] = std::from_chars(first, last, count);
        if (first == last || ec != std::errc() || end != last) {
            *problem = "'" + std::string(first, last) + "' is not a whole number";
            return std::nullopt;
        }
        if (count == 0) {
            *problem = "a count must be at least 1";
            return std::nullopt;
        }
        if (count > maxCount) {
            *problem =
                std::to_string(count) + " is above the most plants a field can hold (" + std::to_string(maxCount) + ")";
            return std::nullopt;
        }
        counts.push_back(count);
        if (comma == text.size()) return counts;
        start = comma + 1;
    }
}

std::optional<uint32_t> parsePathTimes(const std::string& text, std::string* problem) {
    if (text.empty()) return kDefaultPathTimes;
    uint32_t times = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), times);
    if (ec != std::errc() || end != text.data() + text.size() || times < 1 || times > kMaxPathTimes) {
        *problem = "expected a whole number of times along the camera path, 1 to " + std::to_string(kMaxPathTimes);
        return std::nullopt;
    }
    return times;
}

namespace {

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::string dirs = path;
    size_t start = 0;
    while (start <= dirs.size()) {
        const size_t colon = std::min(dirs.find(':', start), dirs.size());
        const std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, colon - start)) / program;
        if (access(candidate.c_str(), X_OK) == 0) return true;
        start = colon + 1;
    }
    return false;
}

} // namespace

std::optional<PlantbenchOptions> parsePlantbenchOptions(int argc, char** argv, int* exitCode) {
    PlantbenchOptions o;
    std::string countsText;

    CLI::App app{"plantbench: measures how the GPU-driven field frame's cost grows with the number of plants\n"
                 "(docs/PLANTBENCH.md). For each count it builds the scene's field with that many plants, renders\n"
                 "warm-up frames, then times the measured frames: GPU ms per pass, frame wall time, plants per LOD."};
    app.set_version_flag("--version", std::string("plantbench ") + kPlantfieldVersion);
    app.footer("Examples:\n"
               "  plantbench --counts 1000,10000,100000 --compare naive\n"
               "  plantbench data/scenes/valley.json --counts 1000000 --path 8   the worst frame along the path\n"
               "  plantbench data/scenes/default.json --counts 1000,10000 --json sweep.json --csv sweep.csv "
               "--plot sweep.png\n" +
               std::string(kFieldToolEnvironment));
    app.add_option("--counts", countsText, "Plant counts to measure, comma-separated, e.g. 1000,10000,100000")
        ->required();
    app.add_option("--frames", o.frames, "Measured frames per count")
        ->check(CLI::Range(1u, 100000u))
        ->default_val(o.frames);
    app.add_option("--warmup", o.warmup, "Frames rendered before measuring (shaders compile on the first)")
        ->check(CLI::Range(0u, 100000u))
        ->default_val(o.warmup);
    FieldToolTexts shared;
    addFieldToolOptions(app, o, shared);
    std::string pathText;
    app.add_option("--path", pathText,
                   "Measure at K times spread evenly over the camera path (default " +
                       std::to_string(kDefaultPathTimes) +
                       ") instead of one --time;\n"
                       "report every time's frame and the worst")
        ->expected(0, 1)
        ->type_name("[K]");
    checkFiniteIn(
        *app.add_option("--fly", o.flyFps,
                        "The camera flies along its path from each time through the warm-up and measured\n"
                        "frames, FPS frames a scene second, as in a window: the shadow cache is redrawn as it\n"
                        "travels, LODs fade, near skeletons change (default: it stays at its time)")
             ->type_name("FPS"),
        1.0, 1000.0);
    app.add_flag("--densify", o.densify,
                 "Fit each count on the scene's terrain by scaling every plant distance (default: the scene's\n"
                 "densities, the planted area and the noise terrain growing with the count)");
    std::string compare;
    app.add_option("--compare", compare, "Also render every count the naive way (full detail, one draw per plant)")
        ->check(CLI::IsMember({"naive"}));
    app.add_option("--naive-max", o.naiveMax, "Skip the naive path above this many plants")
        ->check(CLI::PositiveNumber)
        ->default_val(o.naiveMax);
    app.add_option("--json", o.jsonPath, "Write the results as JSON to this file");
    app.add_option("--csv", o.csvPath, "Write one row per count as CSV to this file");
    app.add_option("--plot", o.plotPath, "Draw ms per pass against plants (log-log) to this PNG with gnuplot");

    if (!parseToolCommandLine(app, argc, argv, "plantbench", exitCode)) return std::nullopt;
    auto fail = [&](const std::string& message) {
        reportBadOption("plantbench", message, exitCode);
        return std::nullopt;
    };
    std::string problem;
    const auto counts = parseCounts(countsText, FIELD_MAX_INSTANCES, &problem);
    if (!counts) return fail("invalid --counts '" + countsText + "': " + problem);
    o.counts = *counts;
    problem = finishFieldToolOptions(shared, o);
    if (!problem.empty()) return fail(problem);
    o.compareNaive = compare == "naive";
    if (app.count("--path")) {
        const auto times = parsePathTimes(pathText, &problem);
        if (!times) return fail("invalid --path '" + pathText + "': " + problem);
        if (app.count("--time"))
            return fail("--path and --time are alternatives: --path measures along the whole path");
        o.pathTimes = *times;
    }
    if (!std::filesystem::is_regular_file(o.scenePath))
        return fail("scene file '" + o.scenePath + "' does not exist or is not a file");
    if (const std::string outputProblem = outputsProblem(o); !outputProblem.empty()) return fail(outputProblem);
    if (!o.plotPath.empty() && !onPath("gnuplot"))
        return fail("--plot needs gnuplot, which is not on PATH: install Debian's gnuplot-nox (tools/deps.sh)");
    return o;
}

std::string outputsProblem(const PlantbenchOptions& o) {
    return flaggedOutputsProblem({{"--json", &o.jsonPath}, {"--csv", &o.csvPath}, {"--plot", &o.plotPath}},
                                 o.scenePath);
}

} // namespace pf
