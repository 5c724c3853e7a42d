// Every file in data/plants (dialect files in data/plants/dialects included)
// parses without diagnostics and derives its derivation length within the
// default budget.

#include <algorithm>
#include <filesystem>

#include "lsystem/vlab/object.h"
#include "test_support.h"

namespace lsys::test {
namespace {

// Paths relative to data/plants: plant files and vlab object folders.
std::vector<std::string> plantFiles() {
    const std::filesystem::path root = dataPath("plants");
    std::vector<std::string> files;
    for (const std::filesystem::path& plant : vlab::findPlants(root))
        files.push_back(plant.lexically_relative(root).string());
    return files;
}

TEST(LsysDataFiles, ThereAreEnough) { EXPECT_GE(plantFiles().size(), 20u); }

TEST(LsysDataFiles, EveryPlantLoadsAndDerives) {
    for (const std::string& file : plantFiles()) {
        SCOPED_TRACE(file);
        const vlab::PlantFile plant = vlab::loadPlant(dataPath("plants/" + file));
        const ParseResult& result = plant.parsed;
        const std::string& source = plant.source;
        ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
        EXPECT_TRUE(source.find("//") != std::string::npos || source.find("/*") != std::string::npos)
            << "each plant file documents where it comes from";
        ModuleString string = derive(result.grammar);
        EXPECT_GT(string.size(), 0u); // tests/turtle interprets each one
    }
}

} // namespace
} // namespace lsys::test
