// Scene files sized to find what grows faster than the file: every step of
// reading one is linear in it (or n log n), a file whose parse would not fit
// the memory budget is refused before parsing, and a placement density past
// the budget is refused before sampling. Each test's input takes the old
// reader far longer than the new one; the tests assert on results and
// messages, never on time.
#include "engine/scene/field_content.h"
#include "lsystem/common/json_reader.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pf {
namespace {

#define PF_SPECIES_NAMED(name) "{\"name\": \"" name "\", " PF_BUSH_LSYSTEM "}"

// A scene file of about `bytes`: one species placed explicitly at plants
// written one a line, removed when the test ends.
struct LargeScene {
    std::filesystem::path file;
    explicit LargeScene(size_t bytes) : file(test::testFolder() / "large.json") {
        std::ofstream out(file, std::ios::binary);
        out << "{\"species\": [{\"name\": \"a\", " PF_BUSH_LSYSTEM ", \"placement\": {\"instances\": [\n";
        const std::string plant = "{\"position\": [1.5, 2.5], \"rotation\": 30, \"scale\": 1.25},\n";
        for (size_t written = 0; written < bytes; written += plant.size()) out << plant;
        out << "{\"position\": [0, 0]}]}}]}\n";
    }
    ~LargeScene() { std::filesystem::remove(file); }
};

TEST(SceneSizes, AFileWhoseParseWouldPassTheMemoryBudgetIsRefusedBeforeParsing) {
    const LargeScene scene(size_t(250) << 20);
    try {
        loadScene(scene.file, lsys::MemoryBudget{uint64_t(1) << 30});
        FAIL() << "parsed a 250 MB scene within 1 GiB";
    } catch (const lsys::MemoryBudgetError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(scene.file.string() + ": memory budget: scene file needs ", 0), 0u) << what;
        EXPECT_NE(what.find("the limit is 1.0 GiB (set with --memory-budget)"), std::string::npos) << what;
    }
}

TEST(SceneSizes, AFileWithinTheBudgetOfItsEstimateLoads) {
    const LargeScene scene(size_t(1) << 20);
    std::ifstream in(scene.file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    const uint64_t estimate = lsys::parsedJsonBytes(text);
    EXPECT_GT(estimate, 8 * text.size()); // each plant an object of three members and an array: many values a byte
    EXPECT_GT(loadScene(scene.file, lsys::MemoryBudget{estimate}).species[0].placement.instances.size(), 15000u);
    EXPECT_THROW(loadScene(scene.file, lsys::MemoryBudget{estimate - 1}), lsys::MemoryBudgetError);
}

// An unknown key of 20 million characters: no did-you-mean (comparing it with
// each known key took the product of their lengths), still located.
TEST(SceneSizes, AHugeUnknownKeyIsNamedWithoutASuggestion) {
    const std::string key(20'000'000, 'x');
    const std::filesystem::path file =
        test::writeFile("huge_key.json", "{\n\"species\": [" PF_SPECIES_NAMED("a") "],\n\"" + key + "\": 1\n}\n");
    try {
        loadScene(file);
        FAIL() << "loaded an unknown key";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(
            what.rfind(file.string() + ":3:1: /" + key + " is an unknown key (expected one of \"description\"", 0), 0u)
            << what.substr(0, 200);
        EXPECT_EQ(what.find("did you mean"), std::string::npos);
    }
}

// 100 000 species: a repeated name is found without comparing every pair.
TEST(SceneSizes, ARepeatedNameAmongAHundredThousandSpeciesIsFound) {
    std::string text = "{\"species\": [\n";
    for (int i = 0; i < 100'000; ++i) text += "{\"name\": \"s" + std::to_string(i) + "\", " PF_BUSH_LSYSTEM "},\n";
    text += PF_SPECIES_NAMED("s17") "\n]}\n";
    const std::filesystem::path file = test::writeFile("many_species.json", text);
    try {
        loadScene(file);
        FAIL() << "loaded a repeated name";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() + ":100002:10: /species/100000/name repeats the name of /species/17");
    }
}

// Densities of 10¹² plants a square metre and of 5 000 (5·10⁷ a hectare,
// within the sampling grid's bound: the old sampling ran past 100 s and
// 2.6 GB on a 100 m terrain): the sampling's grids and plants are counted
// from the density and refused before any plant is sampled.
TEST(SceneSizes, APlacementDensityPastTheMemoryBudgetIsRefusedBeforeSampling) {
    for (const char* density : {"1e8", "5e7"}) { // per hectare: the most a scene takes, and half
        const Scene scene = loadScene(test::writeFile(
            "dense.json", std::string("{\"terrain\": {\"size\": 100}, \"species\": [{\"name\": \"a\", ") +
                              PF_BUSH_LSYSTEM + ", \"placement\": {\"density\": " + density + "}}]}"));
        try {
            placeField(scene, std::nullopt, lsys::MemoryBudget{uint64_t(1) << 30});
            FAIL() << "placed " << density << " plants a hectare within 1 GiB";
        } catch (const lsys::MemoryBudgetError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("memory budget: placement needs ", 0), 0u) << e.what();
        }
    }
}

} // namespace
} // namespace pf
