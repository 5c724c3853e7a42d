// plantbench as a user runs it: small sweeps with JSON, CSV and a plot, and
// requests it must refuse clearly (bad flags, unknown scenes, huge counts).
#include "bad_invocation.h"
#include "run_command.h"

#include "engine/field/field_scopes.h"
#include "engine/image/image.h"
#include "engine/scene/plant_models.h"
#include "engine/scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

const std::string kPlantbench = PLANTBENCH_BIN;
const std::string kSmallScene = std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json";
const std::string kDefaultScene = std::string(PLANTFIELD_DATA_DIR) + "/scenes/default.json";

fs::path scratchDir(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "plantbench" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Plants the scene places by hand: added on top of every requested count.
size_t explicitPlants(const std::string& scenePath) {
    size_t plants = 0;
    for (const Species& s : loadScene(scenePath).species)
        if (s.placement.mode == PlacementMode::Explicit) plants += s.placement.instances.size();
    return plants;
}

// The joints the renderer simulates lie between one shared skeleton (some
// plant follows it) and every model's physics.sharedPhases shared copies
// (engine/physics/field_motion.cpp) plus the near plants' own skeletons, at
// most physics.jointBudget.
struct JointRange {
    uint64_t fewest = 0, most = 0;
};
JointRange expectedJoints(const std::string& scenePath) {
    static std::map<std::string, JointRange> ranges;
    if (!ranges.contains(scenePath)) {
        const Scene scene = loadScene(scenePath);
        uint64_t joints = 0, smallest = ~uint64_t(0);
        for (const PlantModelInfo& model : buildPlantModels(scene).models) {
            joints += model.joints;
            smallest = std::min<uint64_t>(smallest, model.joints);
        }
        const uint64_t shared = joints * std::max(1u, scene.physics.sharedPhases);
        ranges[scenePath] = {smallest, shared + scene.physics.jointBudget};
    }
    return ranges[scenePath];
}

// The field's scopes (kFieldScopes) and plantbench's own "capture" after them.
std::vector<std::string> timedPasses() {
    std::vector<std::string> passes;
    for (const FieldScopeDefinition& scope : kFieldScopes) passes.push_back(scope.name);
    passes.push_back("capture");
    return passes;
}

void expectSpread(const nlohmann::json& spread, const std::string& what) {
    ASSERT_TRUE(spread.is_object()) << what << ": " << spread;
    ASSERT_TRUE(spread["median"].is_number()) << what;
    ASSERT_TRUE(spread["p95"].is_number()) << what;
    EXPECT_GE(spread["median"].get<double>(), 0.0) << what;
    EXPECT_GE(spread["p95"].get<double>(), spread["median"].get<double>()) << what;
}

// Every scope of kFieldScopes and the capture timed, plant counts those asked
// for plus the scene's hand-placed plants, simulated joints in their range,
// naive present with its ratio when asked for.
void expectWellFormedSweep(const nlohmann::json& j, const std::string& scene, const std::vector<uint64_t>& counts,
                           bool naive) {
    EXPECT_EQ(j["scene"], scene);
    EXPECT_TRUE(j["device"].is_string());
    EXPECT_TRUE(j["memory_source"] == "VK_EXT_memory_budget" || j["memory_source"] == "renderer accounting")
        << j["memory_source"];
    ASSERT_EQ(j["results"].size(), counts.size());
    const size_t byHand = explicitPlants(scene);
    for (size_t i = 0; i < counts.size(); ++i) {
        const nlohmann::json& r = j["results"][i];
        const std::string at = std::to_string(counts[i]) + " plants";
        EXPECT_EQ(r["count"], counts[i]) << at;
        EXPECT_EQ(r["instances"], counts[i] + byHand) << at;
        expectSpread(r["frame_ms"], at + " frame_ms");
        expectSpread(r["cpu_ms"], at + " cpu_ms");
        for (const std::string& pass : timedPasses()) expectSpread(r["gpu_ms"][pass], at + " gpu_ms." + pass);
        EXPECT_EQ(r["gpu_ms"].size(), timedPasses().size()) << at << ": " << r["gpu_ms"];
        const uint64_t joints = r["joints_simulated"].get<uint64_t>();
        EXPECT_GT(joints, 0u) << at;
        EXPECT_GE(joints, expectedJoints(scene).fewest) << at;
        EXPECT_LE(joints, expectedJoints(scene).most) << at;
        uint64_t drawn = 0;
        for (const char* lod : {"full", "reduced", "impostor"}) drawn += r["plants_per_lod"][lod].get<uint64_t>();
        EXPECT_GT(drawn + r["canopy_plants"].get<uint64_t>(), 0u) << at << ": plants or far clusters' canopy";
        EXPECT_LE(r["culled"].get<uint64_t>(), counts[i] + byHand) << at;
        EXPECT_GT(r["triangles"].get<uint64_t>(), 0u) << at;
        EXPECT_GT(r["gpu_memory_bytes"].get<uint64_t>(), 0u) << at;
        if (naive) {
            ASSERT_TRUE(r["naive"].is_object()) << at;
            expectSpread(r["naive"]["frame_ms"], at + " naive frame_ms");
            for (const std::string& pass : timedPasses())
                expectSpread(r["naive"]["gpu_ms"][pass], at + " naive gpu_ms." + pass);
            EXPECT_GE(r["naive"]["triangles"].get<uint64_t>(), r["triangles"].get<uint64_t>()) << at;
            EXPECT_NEAR(r["ratio"].get<double>(),
                        r["naive"]["frame_ms"]["median"].get<double>() / r["frame_ms"]["median"].get<double>(), 1e-9);
        } else {
            EXPECT_TRUE(r["naive"].is_null()) << at;
            EXPECT_TRUE(r["ratio"].is_null()) << at;
        }
    }
}

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> cells;
        std::istringstream fields(line);
        for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

// plantbench on test_small.json with `args`, writing JSON and CSV into a
// scratch folder of its own; both read back when it succeeded.
struct SmallSweep {
    CommandResult result;
    nlohmann::json json;
    std::string csv;
};
SmallSweep runSmallSweep(const std::string& name, const std::string& args) {
    const fs::path dir = scratchDir(name);
    const fs::path json = dir / "sweep.json", csv = dir / "sweep.csv";
    SmallSweep sweep;
    sweep.result = runCommand(kPlantbench + " " + kSmallScene + " " + args + " --json " + json.string() + " --csv " +
                              csv.string());
    if (sweep.result.exitCode == 0) {
        sweep.json = nlohmann::json::parse(readText(json));
        sweep.csv = readText(csv);
    }
    return sweep;
}

TEST(PlantbenchCli, SmallSweepWritesJsonAndCsvWithEveryPass) {
    const SmallSweep sweep =
        runSmallSweep("small", "--validation --counts 50,200 --frames 2 --warmup 1 --size 160x90 --compare naive");
    const CommandResult& r = sweep.result;
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ratio"), std::string::npos) << "no summary table:\n" << r.output;

    const nlohmann::json& j = sweep.json;
    EXPECT_EQ(j["frames"], 2);
    EXPECT_EQ(j["warmup"], 1);
    EXPECT_EQ(j["size"], nlohmann::json({160, 90}));
    EXPECT_EQ(j["antialiasing"], "fxaa") << "the default";
    EXPECT_EQ(j["samples"], 1);
    expectWellFormedSweep(j, kSmallScene, {50, 200}, true);

    const auto rows = csvRows(sweep.csv);
    ASSERT_EQ(rows.size(), 3u) << "a header and one row per count";
    EXPECT_EQ(rows[0][0], "count");
    for (size_t i = 1; i < rows.size(); ++i) ASSERT_EQ(rows[i].size(), rows[0].size()) << "row " << i;
    auto column = [&](const std::string& name) {
        return size_t(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
    };
    for (const std::string& pass : timedPasses())
        for (const char* statistic : {"median", "p95"}) {
            const std::string name = "gpu_" + pass + "_ms_" + statistic;
            ASSERT_LT(column(name), rows[0].size()) << name;
            for (size_t i = 1; i < rows.size(); ++i)
                EXPECT_FALSE(rows[i][column(name)].empty()) << name << " row " << i;
        }
    ASSERT_LT(column("joints_simulated"), rows[0].size());
    EXPECT_EQ(rows[1][0], "50");
    EXPECT_EQ(rows[2][0], "200");
    EXPECT_EQ(rows[2][1], std::to_string(200 + explicitPlants(kSmallScene)));
    for (size_t i = 1; i < rows.size(); ++i)
        EXPECT_EQ(rows[i][column("joints_simulated")], j["results"][i - 1]["joints_simulated"].dump()) << "row " << i;
    // The table carries the capture and the joints too.
    EXPECT_NE(r.output.find("capture ms"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("joints"), std::string::npos) << r.output;
}

TEST(PlantbenchCli, DefaultSceneSweepMatchesCounts) {
    const fs::path json = scratchDir("default") / "sweep.json";
    const CommandResult r =
        runCommand(kPlantbench + " --counts 100,300 --frames 2 --warmup 1 --size 160x90 --json " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectWellFormedSweep(nlohmann::json::parse(readText(json)), kDefaultScene, {100, 300}, false);
}

TEST(PlantbenchCli, PathSweepReportsEveryTimeAndTheWorst) {
    const SmallSweep sweep =
        runSmallSweep("path", "--counts 20,40 --frames 2 --warmup 1 --size 64x64 --aa none --path 3 --compare naive");
    ASSERT_EQ(sweep.result.exitCode, 0) << sweep.result.output;
    const nlohmann::json& j = sweep.json;
    EXPECT_EQ(j["path"], 3);
    EXPECT_TRUE(j["time"].is_null());
    expectWellFormedSweep(j, kSmallScene, {20, 40}, true);
    const std::vector<double> times = timesAlongPath(loadScene(kSmallScene).camera, 3);
    for (const nlohmann::json& result : j["results"]) {
        const std::string at = result["count"].dump() + " plants";
        ASSERT_TRUE(result["path"].is_array()) << at;
        ASSERT_EQ(result["path"].size(), times.size()) << at;
        double worst = 0.0, worstTime = -1.0;
        for (size_t i = 0; i < times.size(); ++i) {
            const nlohmann::json& point = result["path"][i];
            EXPECT_DOUBLE_EQ(point["time"].get<double>(), times[i]) << at;
            expectSpread(point["frame_ms"], at + " path frame_ms");
            for (const std::string& pass : timedPasses())
                expectSpread(point["gpu_ms"][pass], at + " path gpu_ms." + pass);
            EXPECT_EQ(point["triangles"].is_number(), true) << at;
            const double ms = point["frame_ms"]["median"].get<double>();
            if (ms > worst) worst = ms, worstTime = times[i];
        }
        // The count's figures are those of the worst time.
        EXPECT_DOUBLE_EQ(result["frame_ms"]["median"].get<double>(), worst) << at;
        EXPECT_DOUBLE_EQ(result["time"].get<double>(), worstTime) << at;
    }
    const auto rows = csvRows(sweep.csv);
    ASSERT_EQ(rows.size(), 3u);
    for (size_t i = 1; i < rows.size(); ++i) ASSERT_EQ(rows[i].size(), rows[0].size()) << "row " << i;
    for (const char* name : {"time", "path_time_1", "path_frame_ms_median_3", "path_frame_ms_p95_3"})
        EXPECT_NE(std::find(rows[0].begin(), rows[0].end(), name), rows[0].end()) << name;
    EXPECT_NE(sweep.result.output.find("along the camera path"), std::string::npos) << sweep.result.output;
}

// test_small's camera travels 7 m a second; the shadow cache serves cameras
// within 8 m of where it was drawn. A still camera draws it on its first
// (warm-up) frame only; one flying at a frame a second draws it again.
TEST(PlantbenchCli, FlyingCameraRedrawsTheShadowCacheAsItTravels) {
    for (const bool fly : {false, true}) {
        const SmallSweep sweep = runSmallSweep(fly ? "fly" : "still", std::string("--counts 20 --frames 4 --warmup 1 "
                                                                                  "--size 64x64 --aa none") +
                                                                          (fly ? " --fly 1" : ""));
        ASSERT_EQ(sweep.result.exitCode, 0) << sweep.result.output;
        const nlohmann::json& j = sweep.json;
        expectWellFormedSweep(j, kSmallScene, {20}, false);
        const uint64_t renders = j["results"][0]["shadow_cache_renders"].get<uint64_t>();
        if (fly) {
            EXPECT_EQ(j["fly_fps"], 1.0);
            EXPECT_GE(renders, 1u);
            EXPECT_NE(sweep.result.output.find("flying at 1.0 frames a second"), std::string::npos)
                << sweep.result.output;
        } else {
            EXPECT_TRUE(j["fly_fps"].is_null());
            EXPECT_EQ(renders, 0u);
        }
    }
}

TEST(PlantbenchCli, RejectsAFlyRateOutOfRange) {
    for (const char* rate : {"0", "nan", "2000"}) {
        const CommandResult r = runCommand(kPlantbench + " --counts 10 --fly " + rate);
        EXPECT_EQ(r.exitCode, 2) << rate << ": " << r.output;
        EXPECT_NE(r.output.find("--fly"), std::string::npos) << r.output;
    }
}

TEST(PlantbenchCli, CountsKeepTheScenesDensitiesUnlessDensified) {
    const fs::path dir = scratchDir("densities");
    // test_small places 20 bushes on its 40 m: 200 need about 126 m, unless densified.
    for (const bool densify : {false, true}) {
        const fs::path json = dir / (densify ? "densified.json" : "natural.json");
        const CommandResult r = runCommand(kPlantbench + " " + kSmallScene +
                                           " --counts 10,200 --frames 1 --warmup 0"
                                           " --size 32x32 --aa none --json " +
                                           json.string() + (densify ? " --densify" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const nlohmann::json j = nlohmann::json::parse(readText(json));
        EXPECT_EQ(j["count_mode"], densify ? "densify" : "natural");
        expectWellFormedSweep(j, kSmallScene, {10, 200}, false);
        EXPECT_EQ(j["results"][0]["terrain_size_m"].get<double>(), 40.0);
        if (densify)
            EXPECT_EQ(j["results"][1]["terrain_size_m"].get<double>(), 40.0);
        else
            EXPECT_GT(j["results"][1]["terrain_size_m"].get<double>(), 110.0);
    }
}

TEST(PlantbenchCli, MsaaIsChosenWithAaAndSamples) {
    const fs::path json = scratchDir("msaa") / "sweep.json";
    const CommandResult r = runCommand(kPlantbench + " " + kSmallScene +
                                       " --validation --counts 20 --frames 1 --warmup 0 --size 64x64 --aa msaa"
                                       " --samples 4 --json " +
                                       json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("4x MSAA"), std::string::npos) << r.output;
    const nlohmann::json j = nlohmann::json::parse(readText(json));
    EXPECT_EQ(j["antialiasing"], "msaa");
    EXPECT_EQ(j["samples"], 4);
}

TEST(PlantbenchCli, NaiveAboveNaiveMaxIsSkippedWithANote) {
    const fs::path json = scratchDir("naive-max") / "sweep.json";
    const CommandResult r = runCommand(kPlantbench + " " + kSmallScene +
                                       " --counts 30,60 --frames 1 --warmup 0 --size 64x64 --compare naive"
                                       " --naive-max 40 --json " +
                                       json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(readText(json));
    EXPECT_TRUE(j["results"][0]["naive"].is_object());
    EXPECT_TRUE(j["results"][1]["naive"].is_null());
    EXPECT_TRUE(j["results"][1]["ratio"].is_null());
    EXPECT_NE(j["results"][1]["note"].get<std::string>().find("--naive-max"), std::string::npos);
}

TEST(PlantbenchCli, PlotWritesReadablePng) {
    ASSERT_EQ(runCommand("command -v gnuplot").exitCode, 0) << "gnuplot is missing: run tools/deps.sh";
    const fs::path dir = scratchDir("plot");
    const fs::path png = dir / "sweep.png";
    const CommandResult r =
        runCommand(kPlantbench + " " + kSmallScene +
                   " --counts 20,40 --frames 1 --warmup 0 --size 64x64 --compare naive --plot " + png.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const RgbaImage image = readPng(png.string());
    EXPECT_GE(image.width, 800u);
    EXPECT_GE(image.height, 800u);
    // Drawn, not blank: some pixels are far from the white background.
    size_t dark = 0;
    for (size_t p = 0; p < image.pixels.size(); p += 4) dark += image.pixels[p] + image.pixels[p + 1] < 200;
    EXPECT_GT(dark, 1000u);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path(), png) << "left behind: " << entry.path();
}

class PlantbenchBadFlags : public ::testing::TestWithParam<BadInvocation> {};

TEST_P(PlantbenchBadFlags, ExitTwoWithoutWriting) {
    expectFailsClearlyWithoutWriting(kPlantbench, GetParam(), scratchDir(std::string("bad-") + GetParam().name), "out");
}

INSTANTIATE_TEST_SUITE_P(
    Flags, PlantbenchBadFlags,
    ::testing::Values(
        BadInvocation{"UnknownOption", "--counts 10 --json OUT.json --frobnicate", "frobnicate"},
        BadInvocation{"NoCounts", "--json OUT.json", "--counts"},
        BadInvocation{"EmptyCounts", "--counts '' --json OUT.json", "--counts"},
        BadInvocation{"ZeroCount", "--counts 10,0 --json OUT.json", "at least 1"},
        BadInvocation{"MalformedCounts", "--counts 10,x5 --json OUT.json", "x5"},
        BadInvocation{"DoubleComma", "--counts 10,,20 --csv OUT.csv", "--counts"},
        BadInvocation{"CountAboveFieldMaximum", "--counts 16777217 --json OUT.json", "16777216"},
        BadInvocation{"ZeroFrames", "--counts 10 --frames 0 --json OUT.json", "--frames"},
        BadInvocation{"MalformedSize", "--counts 10 --size 640by360 --json OUT.json", "--size"},
        BadInvocation{"UnknownCompare", "--counts 10 --compare fancy --json OUT.json", "--compare"},
        BadInvocation{"UnknownAntialiasing", "--counts 10 --aa smaa --json OUT.json", "--aa"},
        BadInvocation{"UnsupportedSamples", "--counts 10 --aa msaa --samples 3 --json OUT.json", "--samples"},
        BadInvocation{"SamplesWithoutMsaa", "--counts 10 --samples 4 --json OUT.json", "--aa msaa"},
        BadInvocation{"MissingOutputFolder", "--counts 10 --json OUT/missing/x.json", "does not exist"},
        BadInvocation{"UnknownScene", "OUT/nosuch.json --counts 10", "does not exist"},
        BadInvocation{"ZeroPathTimes", "--counts 10 --path 0 --json OUT.json", "--path"},
        BadInvocation{"NegativePathTimes", "--counts 10 --path -3 --json OUT.json", "--path"},
        BadInvocation{"MalformedPathTimes", "--counts 10 --path 3x --csv OUT.csv", "--path"},
        BadInvocation{"TooManyPathTimes", "--counts 10 --path 1001 --json OUT.json", "1 to 1000"},
        BadInvocation{"TimeNotANumber", "--counts 10 --time nan --json OUT.json", "not a finite number"},
        BadInvocation{"InfiniteTime", "--counts 10 --time inf --json OUT.json", "not a finite number"},
        BadInvocation{"PathAndTime", "--counts 10 --path 4 --time 2 --json OUT.json", "alternatives"},
        BadInvocation{"MalformedMemoryBudget", "--counts 10 --memory-budget 4Q --json OUT.json", "not a size"},
        // Refused before the sweep: the host check is against the budget.
        BadInvocation{"CountPastTheMemoryBudget", "--counts 1000000 --memory-budget 64M --json OUT.json",
                      "the memory budget is 64.0 MiB"}),
    invocationName);

TEST(PlantbenchCli, MalformedSceneFailsClearlyWithoutWriting) {
    const fs::path dir = scratchDir("bad-scene");
    const fs::path scene = dir / "broken.json";
    std::ofstream(scene) << "{\n  \"species\": [ { \"name\": 3 } ]\n}\n";
    const CommandResult r =
        runCommand(kPlantbench + " " + scene.string() + " --counts 10 --json " + (dir / "out.json").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("broken.json:"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
}

TEST(PlantbenchCli, UnwritableOutputLeavesExistingFileUntouched) {
    const fs::path dir = scratchDir("readonly");
    const fs::path out = dir / "keep.json";
    { std::ofstream(out) << "precious"; }
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    fs::permissions(out, fs::perms::owner_read);
    const CommandResult r = runCommand(kPlantbench + " " + kSmallScene +
                                       " --counts 10 --frames 1 --warmup 0 --size 32x32 --json " + out.string());
    fs::permissions(dir, fs::perms::owner_all);
    // Root may write anywhere; then the file must have been replaced whole.
    if (r.exitCode != 0) {
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_EQ(readText(out), "precious");
    } else {
        EXPECT_NO_THROW(nlohmann::json::parse(readText(out)));
    }
}

// --version prints the CMake project's version, and nothing else runs; the
// physics benchmark (Google Benchmark's flags) answers it alike.
TEST(PlantbenchCli, VersionIsTheProjectsVersion) {
    const CommandResult bench = runCommand(kPlantbench + " --version");
    EXPECT_EQ(bench.exitCode, 0);
    EXPECT_EQ(bench.output, std::string("plantbench ") + PLANTFIELD_VERSION + "\n");
    const CommandResult physics = runCommand(std::string(PHYSICS_BENCH_BIN) + " --version");
    EXPECT_EQ(physics.exitCode, 0);
    EXPECT_EQ(physics.output, std::string("physics_bench ") + PLANTFIELD_VERSION + "\n");
}

TEST(PlantbenchCli, HelpListsEveryOption) {
    const CommandResult r = runCommand(kPlantbench + " --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* flag :
         {"--counts", "--frames", "--warmup", "--size", "--aa", "--samples", "--no-shadows", "--compare", "--naive-max",
          "--json", "--csv", "--plot", "--seed", "--device", "--validation", "--path", "--densify", "--memory-budget"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

} // namespace
} // namespace pf::test
