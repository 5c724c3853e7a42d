// Every file in data/plants (dialect files in data/plants/dialects included)
// parses without diagnostics and derives its derivation length within the
// default budget.

#include <algorithm>
#include <filesystem>

#include "test_support.h"

namespace lsys::test {
namespace {

// Paths relative to data/plants.
std::vector<std::string> plantFiles() {
    const std::filesystem::path root = dataPath("plants");
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
        if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(root).string());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(LsysDataFiles, ThereAreEnough) { EXPECT_GE(plantFiles().size(), 20u); }

TEST(LsysDataFiles, EveryPlantLoadsAndDerives) {
    for (const std::string& file : plantFiles()) {
        SCOPED_TRACE(file);
        ParseResult result = loadDialectFile(dataPath("plants/" + file));
        std::string problem;
        std::string source = readTextFile(dataPath("plants/" + file), problem);
        ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
        EXPECT_TRUE(source.find("//") != std::string::npos || source.find("/*") != std::string::npos)
            << "each plant file documents where it comes from";
        ModuleString string = derive(result.grammar);
        EXPECT_GT(string.size(), 0u); // tests/turtle interprets each one
    }
}

} // namespace
} // namespace lsys::test
