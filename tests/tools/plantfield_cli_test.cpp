// plantfield as a user runs it: captures, bad flags, the window under Xvfb.
#include "bad_invocation.h"
#include "golden.h"
#include "run_command.h"

#include "options.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sys/stat.h>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

const std::string kPlantfield = PLANTFIELD_BIN;

fs::path scratchDir(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "cli" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(ImageSizeOption, ParsesWidthByHeight) {
    const auto size = parseImageSize("640x360");
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->width, 640u);
    EXPECT_EQ(size->height, 360u);
}

TEST(ImageSizeOption, RejectsMalformedZeroAndHugeSizes) {
    for (const char* bad : {"", "640", "x360", "640x", "0x360", "640x0", "-1x5", "64 0x360", "640x360x2", "axb",
                            "16385x16", "99999999999x1"})
        EXPECT_FALSE(parseImageSize(bad).has_value()) << "'" << bad << "' was accepted";
}

TEST(FrameRangeOption, ParsesFirstAndLast) {
    const auto range = parseFrameRange("3:1199");
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->first, 3u);
    EXPECT_EQ(range->last, 1199u);
    EXPECT_EQ(parseFrameRange("0:0")->last, 0u);
}

TEST(FrameRangeOption, RejectsMalformedRanges) {
    for (const char* bad :
         {"", "3", ":", "3:", ":5", "3-5", "3:5:7", "-1:5", "3:x", " 3:5", "3:5 ", "1.5:2", "3:99999999999"})
        EXPECT_FALSE(parseFrameRange(bad).has_value()) << "'" << bad << "' was accepted";
}

TEST(PlantfieldCli, CaptureWritesPngOfRequestedSize) {
    const fs::path out = scratchDir("capture") / "x.png";
    const CommandResult r = runCommand(kPlantfield + " --validation --capture " + out.string() + " --size 640x360");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    const RgbaImage image = readPng(out.string());
    EXPECT_EQ(image.width, 640u);
    EXPECT_EQ(image.height, 360u);
}

TEST(PlantfieldCli, SameInputsGiveBitIdenticalPng) {
    const fs::path dir = scratchDir("determinism");
    for (const char* name : {"a.png", "b.png"}) {
        const CommandResult r =
            runCommand(kPlantfield + " --capture " + (dir / name).string() + " --size 320x200 --time 2");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const auto read = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const std::string a = read(dir / "a.png"), b = read(dir / "b.png");
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "two captures of the same frame differ";
}

class PlantfieldBadFlags : public ::testing::TestWithParam<BadInvocation> {};

TEST_P(PlantfieldBadFlags, FailsClearlyWithoutWriting) {
    // One folder per case: ctest runs the cases in parallel.
    expectFailsClearlyWithoutWriting(kPlantfield, GetParam(), scratchDir(std::string("bad-") + GetParam().name),
                                     "out.png");
}

INSTANTIATE_TEST_SUITE_P(
    Flags, PlantfieldBadFlags,
    ::testing::Values(
        BadInvocation{"UnknownOption", "--capture OUT --frobnicate", "frobnicate"},
        BadInvocation{"ZeroSize", "--capture OUT --size 0x360", "--size"},
        BadInvocation{"MalformedSize", "--capture OUT --size 640by360", "--size"},
        BadInvocation{"HugeSize", "--capture OUT --size 99999x10", "--size"},
        BadInvocation{"MissingOutputFolder", "--capture /nonexistent-dir/x.png", "does not exist"},
        BadInvocation{"UnsupportedSamples", "--capture OUT --aa msaa --samples 3", "samples"},
        BadInvocation{"OneSampleMsaa", "--capture OUT --aa msaa --samples 1", "samples"},
        BadInvocation{"UnknownAntialiasing", "--capture OUT --aa smaa", "--aa"},
        BadInvocation{"SamplesWithoutMsaa", "--capture OUT --samples 4", "--aa msaa"},
        BadInvocation{"SamplesWithFxaa", "--capture OUT --aa fxaa --samples 8", "--aa msaa"},
        BadInvocation{"SamplesWithNone", "--capture OUT --aa none --samples 2", "--aa msaa"},
        BadInvocation{"NoOutputChosen", "--size 640x360", "nothing to do"},
        BadInvocation{"ZeroInstances", "--capture OUT --instances 0", "--instances"},
        BadInvocation{"TooManyInstances", "--capture OUT --instances 16777217", "--instances"},
        BadInvocation{"DensifyWithoutInstances", "--capture OUT --densify", "--densify needs --instances"},
        BadInvocation{"LodOutOfRange", "--capture OUT --lod 3", "--lod"},
        BadInvocation{"FramesWithoutOutDir", "--frames 5", "--out-dir"},
        BadInvocation{"OutDirIsAFile", "--frames 2 --out-dir /dev/null",
                      "cannot write --out-dir: '/dev/null' is not a folder"},
        BadInvocation{"OutDirBelowAFile", "--frames 2 --out-dir /dev/null/frames",
                      "cannot write --out-dir: '/dev/null' is in the way: not a folder"},
        BadInvocation{"FrameRangeWithoutFrames", "--capture OUT --frame-range 0:1", "--frame-range needs"},
        BadInvocation{"FrameRangeInAWindow", "--window --frames 4 --frame-range 0:1", "--frame-range needs"},
        BadInvocation{"MalformedFrameRange", "--frames 4 --out-dir OUT --frame-range 1-2", "expected A:B"},
        BadInvocation{"FrameRangeBackwards", "--frames 4 --out-dir OUT --frame-range 2:1", "comes after the last"},
        BadInvocation{"FrameRangePastTheEnd", "--frames 4 --out-dir OUT --frame-range 2:4", "frames 0 to 3"},
        BadInvocation{"MalformedWind", "--capture OUT --wind fast", "--wind"},
        BadInvocation{"WindTooStrong", "--capture OUT --wind 500,90", "--wind"},
        BadInvocation{"WindDirectionNotANumber", "--capture OUT --wind 10,east", "--wind"},
        BadInvocation{"JointBudgetTooLarge", "--capture OUT --joint-budget 10000001", "--joint-budget"},
        BadInvocation{"JointBudgetNotANumber", "--capture OUT --joint-budget many", "--joint-budget"},
        BadInvocation{"TimeNotANumber", "--capture OUT --time nan", "not a finite number"},
        BadInvocation{"InfiniteTime", "--capture OUT --time inf", "not a finite number"},
        BadInvocation{"TimeTooLate", "--capture OUT --time 1e9", "--time"},
        BadInvocation{"NegativeTime", "--capture OUT --time -1", "--time"},
        BadInvocation{"FpsNotANumber", "--frames 2 --out-dir OUT --fps nan", "not a finite number"},
        BadInvocation{"RenderScaleWithoutWindow", "--capture OUT --render-scale 0.5", "--window"},
        BadInvocation{"WatchWithoutWindow", "--capture OUT --watch", "--watch needs --window"},
        BadInvocation{"WatchAlone", "--watch", "--watch needs --window"},
        BadInvocation{"VideoWithoutFrames", "--capture OUT --video OUT.mp4", "--video needs --frames N"},
        BadInvocation{"VideoOfAnUnknownFormat", "--frames 2 --video OUT.gif", "unknown extension"},
        BadInvocation{"VideoInAMissingFolder", "--frames 2 --video /nonexistent/v.mp4", "cannot write --video"},
        BadInvocation{"RenderScaleTooSmall", "--window --render-scale 0.1", "--render-scale"},
        BadInvocation{"RenderScaleNotANumber", "--window --render-scale half", "--render-scale"},
        BadInvocation{"UnknownScene", "/nonexistent/scene.json --capture OUT", "does not exist"},
        BadInvocation{"UnknownPlant", "--plant /nonexistent/plant.lsys --capture OUT", "does not exist"},
        BadInvocation{"PlantWithAScene", "/nonexistent/scene.json --plant /nonexistent/p.lsys --capture OUT",
                      "not both"},
        BadInvocation{"PlantWithInstances", "--plant /nonexistent/p.lsys --capture OUT --instances 5",
                      "--instances is for scenes"},
        BadInvocation{"PlantFlagsWithoutPlant", "--capture OUT --steps 3", "are for --plant"},
        BadInvocation{"OrbitWithoutPlant", "--capture OUT --orbit 90", "are for --plant"},
        BadInvocation{"MalformedDefine", "--plant /nonexistent/p.lsys --capture OUT -D ANGLE", "invalid -D"},
        BadInvocation{"MalformedMemoryBudget", "--capture OUT --memory-budget lots", "not a size"},
        BadInvocation{"ZeroMemoryBudget", "--capture OUT --memory-budget 0", "--memory-budget"},
        // A million plants need about 122 MiB to place: refused before placing.
        BadInvocation{"InstancesPastTheMemoryBudget", "--capture OUT --instances 1000000 --memory-budget 64M",
                      "memory budget: placement needs 122.1 MiB, the limit is 64.0 MiB"},
        // lavapipe's device memory is the machine's: a frame too large for the budget is refused by name
        // (a 16384x16384 capture was killed by the kernel in a 4 GiB container).
        BadInvocation{"DeviceMemoryPastTheMemoryBudget",
                      "--capture OUT --device llvmpipe --size 8192x8192 --memory-budget 256M",
                      "memory budget: device memory (llvmpipe"}),
    invocationName);

TEST(PlantfieldCli, MalformedSceneNamesFileLineAndColumn) {
    const fs::path dir = scratchDir("bad-scene");
    const fs::path scene = dir / "broken.json";
    { std::ofstream(scene) << "{\n  \"seed\": 1,\n  \"species\": [ { \"name\": \"x\", } ]\n}\n"; }
    const fs::path out = dir / "out.png";
    const CommandResult r = runCommand(kPlantfield + " " + scene.string() + " --capture " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("broken.json:3:"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(PlantfieldCli, UnwritableOutputLeavesExistingFileUntouched) {
    const fs::path dir = scratchDir("readonly");
    const fs::path out = dir / "keep.png";
    { std::ofstream(out) << "precious"; }
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    fs::permissions(out, fs::perms::owner_read);
    const CommandResult r = runCommand(kPlantfield + " --capture " + out.string() + " --size 64x64");
    fs::permissions(dir, fs::perms::owner_all);
    // Root may write anywhere; the check then is only that the file is intact or replaced whole.
    if (r.exitCode != 0) {
        EXPECT_EQ(r.exitCode, 2) << r.output;
        std::ifstream in(out);
        std::string content;
        in >> content;
        EXPECT_EQ(content, "precious");
    } else {
        EXPECT_EQ(readPng(out.string()).width, 64u);
    }
}

TEST(PlantfieldCli, CaptureReplacesOnlyRegularFiles) {
    const fs::path dir = scratchDir("not-regular");
    const fs::path fifo = dir / "pipe.png", locked = dir / "locked.png";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    { std::ofstream(locked) << "precious"; }
    fs::permissions(locked, fs::perms::owner_read);
    for (const auto& [target, reason] : {std::pair{fifo, "is a fifo"}, std::pair{locked, "is read-only"}}) {
        const CommandResult r = runCommand(kPlantfield + " --capture " + target.string() + " --size 64x64");
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
    }
    EXPECT_TRUE(fs::is_fifo(fifo));
    std::ifstream in(locked);
    std::string content;
    in >> content;
    EXPECT_EQ(content, "precious");
}

// Writes NAME.lsys with `lsystem` and a scene of two NAME plants on a small
// terrain into `dir`; returns the scene's path.
std::string sceneOfOneSpecies(const fs::path& dir, const std::string& name, const std::string& lsystem) {
    std::ofstream(dir / (name + ".lsys")) << lsystem;
    std::ofstream(dir / "scene.json") << R"({ "terrain": { "size": 20, "resolution": 17 }, "species": [ { "name": ")"
                                      << name << R"(", "lsystem": ")" << name
                                      << R"(.lsys", "placement": { "count": 2 } } ] })";
    return (dir / "scene.json").string();
}

// A species that grows past --memory-budget is refused with the stage, the
// need and the limit, naming the species, and exit 2 (bad input, as a
// species past the module budget), nothing written.
TEST(PlantfieldCli, SpeciesPastTheMemoryBudgetIsRefusedByName) {
    const fs::path dir = scratchDir("species-budget");
    const fs::path out = dir / "out.png";
    const CommandResult r = runCommand(
        kPlantfield + " " + sceneOfOneSpecies(dir, "bush", "derivation length: 9\nAxiom: F\nF -> F[+F]F[-F]F\n") +
        " --capture " + out.string() + " --size 32x32 --memory-budget 16M");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("species 'bush'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("memory budget: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the limit is 16.0 MiB"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

// A scene's malformed L-system is bad input like a malformed scene: exit 2
// with the species, the file, line and column.
TEST(PlantfieldCli, MalformedSpeciesFileExitsTwoWithFileLineAndColumn) {
    const fs::path dir = scratchDir("species-malformed");
    const CommandResult r =
        runCommand(kPlantfield + " " + sceneOfOneSpecies(dir, "bad", "Axiom: F\nF -> F[+F\nthis is not a rule\n") +
                   " --capture " + (dir / "out.png").string() + " --size 32x32");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("species 'bad'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bad.lsys:3:1"), std::string::npos) << r.output;
}

// Species whose L-systems draw nothing (no segment, no joint: empty
// buffers on the GPU) render as the bare terrain.
TEST(PlantfieldCli, SpeciesThatDrawNothingRenderTheTerrain) {
    const fs::path dir = scratchDir("draws-nothing");
    { std::ofstream(dir / "nothing.lsys") << "Axiom: A\n"; }
    { std::ofstream(dir / "unclosed.lsys") << "Axiom: {.f.f.\n"; }
    {
        std::ofstream(dir / "scene.json") << R"({
  "terrain": { "size": 20, "resolution": 17 },
  "species": [
    { "name": "nothing", "lsystem": "nothing.lsys", "placement": { "count": 5 } },
    { "name": "unclosed", "lsystem": "unclosed.lsys", "placement": { "count": 5 } }
  ]
})";
    }
    const fs::path out = dir / "out.png";
    const CommandResult r = runCommand(kPlantfield + " " + (dir / "scene.json").string() +
                                       " --validation --size 64x36 --capture " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_EQ(readPng(out.string()).width, 64u);
}

// --version prints the CMake project's version, and nothing else runs.
TEST(PlantfieldCli, VersionIsTheProjectsVersion) {
    const CommandResult r = runCommand(kPlantfield + " --version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.output, std::string("plantfield ") + PLANTFIELD_VERSION + "\n");
}

TEST(PlantfieldCli, HelpListsEveryOption) {
    const CommandResult r = runCommand(kPlantfield + " --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* flag : {"--capture",     "--size",         "--window",        "--frames",
                             "--frame-range", "--time",         "--device",        "--validation",
                             "--wind",        "--joint-budget", "--physics-check", "--instances",
                             "--densify",     "--aa",           "--samples",       "--no-shadow-cache",
                             "--no-clusters", "--occlusion",    "--render-scale",  "--memory-budget",
                             "--plant",       "--plant-height", "--steps",         "--orbit",
                             "--orbit-speed", "--define",       "--watch"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

// Each --aa method renders under validation, with its timer scope in the
// statistics; an MSAA count beyond the device's (lavapipe has 1 and 4) is
// lowered for the pipelines and the target alike. FXAA changes the frame's
// edges, so its capture differs from the one without anti-aliasing.
TEST(PlantfieldCli, EveryAntialiasingRendersUnderValidation) {
    const fs::path dir = scratchDir("antialiasing");
    std::map<std::string, std::string> captures;
    for (const char* flags : {"--aa fxaa", "--aa msaa --samples 8", "--aa msaa --samples 2", "--aa none"}) {
        const fs::path out = dir / (std::to_string(captures.size()) + ".png");
        const CommandResult r = runCommand(kPlantfield + " --validation --stats --size 160x90 --time 2 " + flags +
                                           " --capture " + out.string());
        ASSERT_EQ(r.exitCode, 0) << flags << "\n" << r.output;
        EXPECT_EQ(r.output.find("validation"), std::string::npos) << flags << "\n" << r.output;
        EXPECT_NE(r.output.find("\"antialias\""), std::string::npos) << flags << ": no antialias scope\n" << r.output;
        const RgbaImage image = readPng(out.string());
        captures[flags] = std::string(image.pixels.begin(), image.pixels.end());
    }
    EXPECT_NE(captures["--aa fxaa"], captures["--aa none"]);
}

TEST(PlantfieldCli, WindowUnderXvfbRendersFrames) {
    ASSERT_EQ(runCommand("command -v xvfb-run").exitCode, 0) << "xvfb-run is missing: run tools/deps.sh";
    const fs::path out = scratchDir("window") / "window.png";
    const CommandResult r = runCommand("xvfb-run -a -s '-screen 0 640x480x24' " + kPlantfield +
                                       " --validation --window --frames 30 --size 320x240 --capture " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("30 frames"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    const RgbaImage image = readPng(out.string());
    ASSERT_EQ(image.width, 320u);
    // Not empty: the screenshot holds many distinct colours (sky, ground, bark).
    std::set<uint32_t> colors;
    for (size_t p = 0; p < image.pixels.size(); p += 4)
        colors.insert(image.pixels[p] | image.pixels[p + 1] << 8 | image.pixels[p + 2] << 16);
    EXPECT_GT(colors.size(), 100u);
}

// A fixed render scale renders the window's frames at that share of its
// size; the screenshot is still the window's size.
TEST(PlantfieldCli, WindowRendersAtAFixedRenderScale) {
    ASSERT_EQ(runCommand("command -v xvfb-run").exitCode, 0) << "xvfb-run is missing: run tools/deps.sh";
    const fs::path out = scratchDir("window-scale") / "window.png";
    const CommandResult r =
        runCommand("xvfb-run -a -s '-screen 0 640x480x24' " + kPlantfield +
                   " --validation --window --frames 10 --size 320x240 --render-scale 0.5 --capture " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the last rendered at 160x120"), std::string::npos) << r.output;
    EXPECT_EQ(readPng(out.string()).width, 320u);
}

// --joint-budget replaces the scene's: with none, only the shared copies of
// each model are simulated; with a budget, near plants get their own too.
TEST(PlantfieldCli, JointBudgetOnTheCommandLineSetsTheSimulatedJoints) {
    auto simulated = [](const std::string& budget) {
        const CommandResult r = runCommand(kPlantfield + " --stats --size 64x36 --joint-budget " + budget);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        const size_t start = r.output.find('{');
        if (start == std::string::npos) return uint64_t(0);
        return nlohmann::json::parse(r.output.substr(start)).at("joints_simulated").get<uint64_t>();
    };
    const uint64_t shared = simulated("0"), withNear = simulated("100000");
    EXPECT_GT(shared, 0u);
    EXPECT_GT(withNear, shared);
    EXPECT_LE(withNear - shared, 100000u);
}

// A sequence from a camera that barely moves draws the shadow map's static
// casters once; --no-shadow-cache draws them every frame.
TEST(PlantfieldCli, NoShadowCacheDrawsTheStaticCastersEveryFrame) {
    auto cacheRenders = [](const std::string& flags) {
        const fs::path dir = scratchDir("shadow_cache");
        const CommandResult r = runCommand(kPlantfield + " --stats --size 64x36 --frames 3 --fps 1000 --out-dir " +
                                           dir.string() + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        const size_t start = r.output.find('{');
        if (start == std::string::npos) return uint64_t(0);
        return nlohmann::json::parse(r.output.substr(start)).at("shadow").at("cache_renders").get<uint64_t>();
    };
    EXPECT_EQ(cacheRenders(""), 1u);
    EXPECT_EQ(cacheRenders("--no-shadow-cache"), 3u);
}

// A farm renders a sequence in ranges: each range's files are the whole
// run's, byte for byte, though every frame carries the plants' motion, LOD
// fades and the shadow cache to the next. From t = 10 s the whole run's
// motion started from rest at 5 s, so a range that started its own (from
// rest at its first frame's time − 5 s) would differ: with every plant at
// LOD 0 its skeletons sway visibly even at 64x48 (measured: a capture at
// frame 1's time differs from the whole run's frame 1).
TEST(PlantfieldCli, FrameRangeMatchesTheWholeRunsFrames) {
    const std::string scene = (fs::path(defaultScenePath()).parent_path() / "gust.json").string();
    const std::string sequence =
        kPlantfield + " " + scene + " --validation --lod 0 --size 64x48 --time 10 --fps 10 --frames 4 --out-dir ";
    const fs::path whole = scratchDir("frame-range-whole"), part = scratchDir("frame-range-part");
    const CommandResult all = runCommand(sequence + whole.string());
    ASSERT_EQ(all.exitCode, 0) << all.output;
    const CommandResult range = runCommand(sequence + part.string() + " --frame-range 1:2");
    ASSERT_EQ(range.exitCode, 0) << range.output;
    EXPECT_EQ(range.output.find("validation"), std::string::npos) << range.output;
    EXPECT_NE(range.output.find("frames 1 to 2 of 4 -> "), std::string::npos) << range.output;
    std::set<std::string> written;
    for (const fs::directory_entry& entry : fs::directory_iterator(part)) written.insert(entry.path().filename());
    EXPECT_EQ(written, (std::set<std::string>{"frame_0001.png", "frame_0002.png"}));
    const auto bytes = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (const std::string& name : written) {
        const std::string expected = bytes(whole / name);
        ASSERT_FALSE(expected.empty()) << name;
        EXPECT_TRUE(bytes(part / name) == expected) << name << " differs from the whole run's";
    }
}

// --video encodes the frames --out-dir writes: decoded again, each video
// frame is its PNG within H.264's loss (CRF 18 at 64x48 measured a mean
// difference of 2.6 of 255 a channel) and further from its neighbours
// (measured 10 and more, two seconds of flight apart).
TEST(PlantfieldCli, VideoHoldsTheSequencesFrames) {
    ASSERT_EQ(runCommand("command -v ffmpeg").exitCode, 0) << "ffmpeg is missing: run tools/deps.sh";
    const fs::path dir = scratchDir("video");
    const fs::path video = dir / "flight.mkv", raw = dir / "decoded.rgba";
    const CommandResult r = runCommand(kPlantfield + " --validation --size 64x48 --fps 0.5 --frames 3 --out-dir " +
                                       (dir / "frames").string() + " --video " + video.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("3 frames -> "), std::string::npos) << r.output;
    const CommandResult decode =
        runCommand("ffmpeg -v error -i " + video.string() + " -f rawvideo -pix_fmt rgba " + raw.string());
    ASSERT_EQ(decode.exitCode, 0) << decode.output;
    std::ifstream in(raw, std::ios::binary);
    const std::string decoded(std::istreambuf_iterator<char>(in), {});
    const size_t frameBytes = 64 * 48 * 4;
    ASSERT_EQ(decoded.size(), 3 * frameBytes);
    const auto meanDifference = [&](size_t videoFrame, const RgbaImage& png) {
        double sum = 0;
        for (size_t i = 0; i < frameBytes; ++i)
            if (i % 4 != 3) sum += std::abs(int(uint8_t(decoded[videoFrame * frameBytes + i])) - int(png.pixels[i]));
        return sum / double(frameBytes / 4 * 3);
    };
    std::vector<RgbaImage> pngs;
    for (int i = 0; i < 3; ++i)
        pngs.push_back(readPng((dir / "frames" / ("frame_000" + std::to_string(i) + ".png")).string()));
    for (size_t v = 0; v < 3; ++v) {
        const double own = meanDifference(v, pngs[v]);
        EXPECT_LT(own, 5.0) << "video frame " << v;
        for (size_t other = 0; other < 3; ++other) {
            if (other != v) {
                EXPECT_LT(own, meanDifference(v, pngs[other])) << "video frame " << v << " vs " << other;
            }
        }
    }
}

// The data folder's plants (data/plants).
fs::path plantsDir() { return fs::path(defaultScenePath()).parent_path().parent_path() / "plants"; }

// Pixels of a --plant capture that are the plant's: brown bark (red above
// green and blue), where the ground is green and the sky and haze blue-grey.
struct PlantPixels {
    size_t count = 0;
    uint32_t minX = ~0u, maxX = 0, minY = ~0u, maxY = 0;
    bool inCentreColumn = false;
};
PlantPixels brownPixels(const RgbaImage& image) {
    PlantPixels found;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
            if (!(p[0] > p[1] + 8 && p[0] > p[2] + 8)) continue;
            ++found.count;
            found.minX = std::min(found.minX, x), found.maxX = std::max(found.maxX, x);
            found.minY = std::min(found.minY, y), found.maxY = std::max(found.maxY, y);
            if (x == image.width / 2) found.inCentreColumn = true;
        }
    return found;
}

// --plant frames one plant with the orbit camera: the brown tree spans most
// of the frame's height, centred, and a plant that draws nothing leaves only
// ground and sky (so the colour test sees the plant, not the background).
TEST(PlantfieldCli, PlantPreviewFramesThePlant) {
    const fs::path dir = scratchDir("plant-preview");
    { std::ofstream(dir / "empty.lsys") << "Axiom: A\n"; }
    const auto capture = [&](const fs::path& plant, const std::string& name) {
        const fs::path out = dir / name;
        const CommandResult r = runCommand(kPlantfield + " --validation --size 96x96 --plant " + plant.string() +
                                           " --capture " + out.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
        return readPng(out.string());
    };
    const RgbaImage tree = capture(plantsDir() / "monopodial_tree.lsys", "tree.png");
    ASSERT_EQ(tree.width, 96u);
    const PlantPixels plant = brownPixels(tree);
    ASSERT_GT(plant.count, 0u) << "no plant in the frame";
    EXPECT_GE(plant.maxY - plant.minY + 1, 48u) << "the plant spans under half the frame's height";
    EXPECT_LE(plant.maxY - plant.minY + 1, 95u) << "the plant is cut at the frame's top or bottom";
    const double centreX = 0.5 * (plant.minX + plant.maxX), centreY = 0.5 * (plant.minY + plant.maxY);
    EXPECT_NEAR(centreX, 47.5, 12.0);
    EXPECT_NEAR(centreY, 47.5, 12.0);
    EXPECT_TRUE(plant.inCentreColumn);
    EXPECT_EQ(brownPixels(capture(dir / "empty.lsys", "empty.png")).count, 0u);
}

// --plant with a scene file, or a malformed plant: exit 2 naming the file,
// line and column, nothing written.
TEST(PlantfieldCli, PlantPreviewRefusesASceneAndMalformedPlants) {
    const fs::path dir = scratchDir("plant-preview-bad");
    { std::ofstream(dir / "bad.lsys") << "Axiom: F\nF -> F[+F\nthis is not a rule\n"; }
    const fs::path out = dir / "out.png";
    CommandResult r = runCommand(kPlantfield + " " + defaultScenePath() + " --plant " +
                                 (plantsDir() / "monopodial_tree.lsys").string() + " --capture " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("not both"), std::string::npos) << r.output;
    r = runCommand(kPlantfield + " --plant " + (dir / "bad.lsys").string() + " --size 32x32 --capture " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("bad.lsys:3:1"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

// A vlab object folder previews as a file does; --orbit-speed turns the
// camera along a sequence, so its frames differ; --steps and -D reach the
// plant (a shorter derivation or another #define draws a different plant).
TEST(PlantfieldCli, PlantPreviewOfAVlabObjectOrbits) {
    const fs::path dir = scratchDir("plant-preview-vlab");
    const std::string plant = (plantsDir() / "abop" / "fig2_6a_monopodial_tree").string();
    const CommandResult r = runCommand(kPlantfield + " --validation --size 64x64 --plant " + plant +
                                       " --frames 2 --fps 1 --orbit-speed 90 --out-dir " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    const RgbaImage first = readPng((dir / "frame_0000.png").string());
    const RgbaImage second = readPng((dir / "frame_0001.png").string());
    ASSERT_EQ(first.width, 64u);
    EXPECT_NE(first.pixels, second.pixels) << "the orbit did not turn";
    for (const char* flags : {"", "--steps 2", "-D a0=10"}) {
        const fs::path changed = dir / "changed.png";
        const CommandResult c =
            runCommand(kPlantfield + " --size 64x64 --plant " + plant + " " + flags + " --capture " + changed.string());
        ASSERT_EQ(c.exitCode, 0) << flags << "\n" << c.output;
        // Without flags, the sequence's first frame: the same view, so a difference is the plant's.
        if (*flags == '\0')
            EXPECT_EQ(readPng(changed.string()).pixels, first.pixels) << "a capture differs from frame 0";
        else
            EXPECT_NE(readPng(changed.string()).pixels, first.pixels) << flags << " did not change the plant";
    }
}

TEST(PlantfieldCli, PhysicsCheckMatchesCpuReference) {
    const CommandResult r = runCommand(kPlantfield + " --physics-check --validation");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    // The JSON line among the progress lines of stderr.
    const size_t start = r.output.find("{\"joints\"");
    ASSERT_NE(start, std::string::npos) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output.substr(start, r.output.find('\n', start) - start));
    EXPECT_GT(j.at("joints").get<uint32_t>(), 0u);
    EXPECT_EQ(j.at("steps").get<uint32_t>(), 600u);
    EXPECT_LT(j.at("max_deviation_rad").get<double>(), 1e-3);
    EXPECT_GE(j.at("gpu_ms").get<double>(), 0.0);
    EXPECT_GE(j.at("cpu_ms").get<double>(), 0.0);
}

} // namespace
} // namespace pf::test
