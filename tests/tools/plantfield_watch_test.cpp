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

// The same little tree: bark (material 0, brown), then pollen (3, yellow).
const char* const kBrownTree = "Axiom: !(0.3)F(2)[+(30)!(0.2)F(1.5)][-(30)!(0.2)F(1.5)]\n";
const char* const kYellowTree = "Axiom: ;(3)!(0.3)F(2)[+(30)!(0.2)F(1.5)][-(30)!(0.2)F(1.5)]\n";

TEST(PlantfieldWatch, TheWindowRegrowsThePlantAtEachSaveAndShowsErrors) {
    ASSERT_EQ(runCommand("command -v xvfb-run").exitCode, 0) << "xvfb-run is missing: run tools/deps.sh";
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "cli" / "watch";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path plant = dir / "plant.lsys", log = dir / "log.txt", pidFile = dir / "pid", rcFile = dir / "rc",
                   shot = dir / "shot.png";
    { std::ofstream(plant) << kBrownTree; }

    // In the background: plantfield's pid and, once it ends, its exit code land in files.
    const std::string command =
        "xvfb-run -a -s '-screen 0 640x480x24' sh -c '\"$0\" \"$@\" & echo $! > " + pidFile.string() +
        "; wait $!; echo $? > " + rcFile.string() + "' " + PLANTFIELD_BIN + " --validation --window --watch --plant " +
        plant.string() + " --frames 20000 --size 160x120 --capture " + shot.string() + " > " + log.string() + " 2>&1 &";
    ASSERT_EQ(std::system(command.c_str()), 0);
    auto pid = [&] { return std::atoi(fileText(pidFile).c_str()); };
    auto killAndFail = [&](const std::string& waitedFor) {
        if (pid() > 0) kill(pid(), SIGKILL);
        FAIL() << "timed out waiting for " << waitedFor << "\n" << fileText(log);
    };

    if (!waitForText(log, "plantfield: watching", 120s)) return killAndFail("the window to start watching");
    { std::ofstream(plant) << "Axiom: F\nthis is not a rule\n"; }
    if (!waitForText(log, "plant.lsys:2:", 60s)) return killAndFail("the error of the broken save");
    { std::ofstream(plant) << kYellowTree; }
    if (!waitForText(log, "plantfield: reloaded", 60s)) return killAndFail("the reload of the fixed save");
    ASSERT_TRUE(waitForText(pidFile, "\n", 10s));
    kill(pid(), SIGTERM); // closes the window as its close button does: the screenshot is written
    if (!waitForText(rcFile, "\n", 60s)) return killAndFail("the window to close");

    const std::string output = fileText(log);
    EXPECT_EQ(std::atoi(fileText(rcFile).c_str()), 0) << output;
    EXPECT_EQ(output.find("validation"), std::string::npos) << output;
    EXPECT_NE(output.find("error"), std::string::npos) << output;
    EXPECT_NE(output.find("still drawing the last good build"), std::string::npos) << output;
    const RgbaImage image = readPng(shot.string());
    ASSERT_EQ(image.width, 160u);
    const PlantColors colors = plantColors(image);
    EXPECT_GT(colors.yellow, 100u) << "the fixed save's yellow plant is not drawn";
    EXPECT_EQ(colors.brown, 0u) << "the first save's brown plant is still drawn";
}

} // namespace
} // namespace pf::test
