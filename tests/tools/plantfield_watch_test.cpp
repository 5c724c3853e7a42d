// plantfield --window --watch under Xvfb, as a modeller uses it: the plant
// file is saved broken, then fixed in another colour, while the window runs.
// The run is bounded twice: by --frames and by a timeout on every wait, after
// which the process is killed and the test fails; it never hangs.
#include "golden.h"
#include "run_command.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace pf::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Waits until `file` holds `text`; false after `timeout`.
bool waitForText(const fs::path& file, const std::string& text, std::chrono::seconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (fileText(file).find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(50ms);
    }
    return true;
}

// Pixels of the plant: bright pale yellow (pollen), or redder than green and
// blue (bark, as PlantPreviewFramesThePlant finds it); the sky is blue and
// the ground green and darker.
struct PlantColors {
    size_t brown = 0, yellow = 0;
};

PlantColors plantColors(const RgbaImage& image) {
    PlantColors found;
    for (size_t p = 0; p < image.pixels.size(); p += 4) {
        const int r = image.pixels[p], g = image.pixels[p + 1], b = image.pixels[p + 2];
        if (r > 200 && g > 200 && b + 30 < g)
            ++found.yellow;
        else if (r > g + 8 && r > b + 8)
            ++found.brown;
    }
    return found;
}

// plantfield --window --watch ARGS under Xvfb in the background: its pid
// and, once it ends, its exit code land in files of `dir`, its output in log.txt.
struct WatchedWindow {
    fs::path dir, log, pidFile, rcFile;

    WatchedWindow(const fs::path& folder, const std::string& arguments)
        : dir(folder), log(folder / "log.txt"), pidFile(folder / "pid"), rcFile(folder / "rc") {
        const std::string command = "xvfb-run -a -s '-screen 0 640x480x24' sh -c '\"$0\" \"$@\" & echo $! > " +
                                    pidFile.string() + "; wait $!; echo $? > " + rcFile.string() + "' " +
                                    PLANTFIELD_BIN + " --validation --window --watch " + arguments + " > " +
                                    log.string() + " 2>&1 &";
        started = std::system(command.c_str()) == 0;
    }
    int pid() const { return std::atoi(fileText(pidFile).c_str()); }
    // Closes the window as its close button does (the screenshot is written)
    // and returns its exit code; -1 when it did not end in time (then killed).
    int close() const {
        if (!waitForText(pidFile, "\n", 10s)) return -1;
        kill(pid(), SIGTERM);
        if (waitForText(rcFile, "\n", 60s)) return std::atoi(fileText(rcFile).c_str());
        kill(pid(), SIGKILL);
        return -1;
    }
    // Kills the window and fails the test, naming what it waited for.
    void killAndFail(const std::string& waitedFor) const {
        if (pid() > 0) kill(pid(), SIGKILL);
        ADD_FAILURE() << "timed out waiting for " << waitedFor << "\n" << fileText(log);
    }
    bool started = false;
};

// The same little tree: bark (material 0, brown), then pollen (3, yellow).
const char* const kBrownTree = "Axiom: !(0.3)F(2)[+(30)!(0.2)F(1.5)][-(30)!(0.2)F(1.5)]\n";
const char* const kYellowTree = "Axiom: ;(3)!(0.3)F(2)[+(30)!(0.2)F(1.5)][-(30)!(0.2)F(1.5)]\n";

TEST(PlantfieldWatch, TheWindowRegrowsThePlantAtEachSaveAndShowsErrors) {
    ASSERT_EQ(runCommand("command -v xvfb-run").exitCode, 0) << "xvfb-run is missing: run tools/deps.sh";
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "cli" / "watch";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path plant = dir / "plant.lsys", shot = dir / "shot.png";
    { std::ofstream(plant) << kBrownTree; }
    const WatchedWindow window(dir, "--plant " + plant.string() + " --frames 20000 --size 160x120 --capture " +
                                        shot.string());
    ASSERT_TRUE(window.started);

    if (!waitForText(window.log, "plantfield: watching", 120s))
        return window.killAndFail("the window to start watching");
    { std::ofstream(plant) << "Axiom: F\nthis is not a rule\n"; }
    if (!waitForText(window.log, "plant.lsys:2:", 60s)) return window.killAndFail("the error of the broken save");
    { std::ofstream(plant) << kYellowTree; }
    if (!waitForText(window.log, "plantfield: reloaded", 60s))
        return window.killAndFail("the reload of the fixed save");
    const int exitCode = window.close();

    const std::string output = fileText(window.log);
    EXPECT_EQ(exitCode, 0) << output;
    EXPECT_EQ(output.find("validation"), std::string::npos) << output;
    EXPECT_NE(output.find("error"), std::string::npos) << output;
    EXPECT_NE(output.find("still drawing the last good build"), std::string::npos) << output;
    const RgbaImage image = readPng(shot.string());
    ASSERT_EQ(image.width, 160u);
    const PlantColors colors = plantColors(image);
    EXPECT_GT(colors.yellow, 100u) << "the fixed save's yellow plant is not drawn";
    EXPECT_EQ(colors.brown, 0u) << "the first save's brown plant is still drawn";
}

// A file first read by a rebuild (here a mesh the saved plant starts to
// use) is an input of the run as much as the first build's: the window's
// screenshot may not replace it, though the rebuild ran on another thread.
TEST(PlantfieldWatch, TheScreenshotNeverReplacesAFileARebuildRead) {
    ASSERT_EQ(runCommand("command -v xvfb-run").exitCode, 0) << "xvfb-run is missing: run tools/deps.sh";
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "cli" / "watch_inputs";
    fs::remove_all(dir);
    fs::create_directories(dir / "meshes");
    const fs::path plant = dir / "plant.lsys", mesh = dir / "meshes" / "blob.glb";
    { std::ofstream(plant) << kBrownTree; }
    { std::ofstream(mesh) << "a modeller's only copy"; }
    const WatchedWindow window(dir,
                               "--plant " + plant.string() + " --frames 20000 --size 64x48 --capture " + mesh.string());
    ASSERT_TRUE(window.started);

    if (!waitForText(window.log, "plantfield: watching", 120s))
        return window.killAndFail("the window to start watching");
    { std::ofstream(plant) << "Axiom: F(1)~blob\n"; } // reads meshes/blob.glb, which is not a mesh
    if (!waitForText(window.log, "still drawing the last good build", 60s))
        return window.killAndFail("the rebuild's error");
    const int exitCode = window.close();

    const std::string output = fileText(window.log);
    EXPECT_EQ(exitCode, 2) << output;
    EXPECT_NE(output.find("never replaces a file the run reads"), std::string::npos) << output;
    EXPECT_EQ(fileText(mesh), "a modeller's only copy");
}

} // namespace
} // namespace pf::test
