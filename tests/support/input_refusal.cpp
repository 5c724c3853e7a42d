#include "input_refusal.h"

#include "run_command.h"
#include "test_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace pf::test {
namespace {

std::string bytesOf(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace

std::filesystem::path emptyTestFolder(std::string_view area) {
    const std::filesystem::path folder = testFolder(area);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

std::filesystem::path bushScene(const std::filesystem::path& dir, const std::filesystem::path& data) {
    std::filesystem::copy(data / "plants" / "stochastic_bush.lsys", dir / "bush.lsys");
    std::ofstream(dir / "scene.json") << R"({ "terrain": { "size": 20, "resolution": 17 }, "species": [ )"
                                      << R"({ "name": "bush", "lsystem": "bush.lsys", "steps": 2, )"
                                      << R"("placement": { "count": 2 } } ] })";
    return dir / "scene.json";
}

void expectRefusedAsInput(const std::string& command, const std::filesystem::path& input) {
    const std::string before = bytesOf(input);
    ASSERT_FALSE(before.empty()) << input << " is missing or empty: nothing to protect";
    const CommandResult r = runCommand(command);
    EXPECT_EQ(r.exitCode, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("an output never replaces a file the run reads"), std::string::npos) << command << "\n"
                                                                                                 << r.output;
    EXPECT_EQ(bytesOf(input), before) << command << " changed " << input;
}

} // namespace pf::test
