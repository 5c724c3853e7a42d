// Species given by a model file instead of an L-system: a ramification tree
// (.ram.json, Tankard 2001 §3.3) or a component plant (.comp.json, §3.2).
// They load, their errors are located, and their plant models are built like
// an L-system's: with geometry and joints, the same per variant, and (for
// ramification trees) a different tree for each variant.
#include "engine/scene/plant_models.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace pf {
namespace {

TEST(ModelSpecies, LoadsATreeTypeAndAComponentPlant) {
    const std::filesystem::path file = test::writeFile(
        "models.json",
        "{ \"species\": [\n"
        "  { \"name\": \"oak\", \"model\": \"" PLANTFIELD_DATA_DIR "/ramified/oak.ram.json\", "
        "\"variants\": 2, \"height\": 9 },\n"
        "  { \"name\": \"palm\", \"model\": \"" PLANTFIELD_DATA_DIR "/components/coconut_palm.comp.json\" } ] }");
    const Scene scene = loadScene(file);
    ASSERT_EQ(scene.species.size(), 2u);
    EXPECT_EQ(scene.species[0].model, std::filesystem::path(PLANTFIELD_DATA_DIR "/ramified/oak.ram.json"));
    EXPECT_TRUE(scene.species[0].lsystem.empty());
    EXPECT_EQ(scene.species[0].variants, 2u);
    EXPECT_EQ(scene.species[0].height, 9.0f);
    EXPECT_EQ(scene.species[1].model, std::filesystem::path(PLANTFIELD_DATA_DIR "/components/coconut_palm.comp.json"));
}

Scene sceneOfModel(const std::filesystem::path& model, uint32_t variants) {
    Scene scene;
    Species species;
    species.name = "probe";
    species.model = model;
    species.variants = variants;
    species.height = 5.0f;
    scene.species.push_back(species);
    return scene;
}

// The full-detail positions of a model, both draw classes.
std::vector<float> positionsOf(const PlantModelPool& pool, const PlantModelInfo& model) {
    std::vector<float> positions;
    for (const MeshRange& range : model.meshes[LOD_FULL])
        for (uint32_t i = 0; i < range.indexCount; ++i)
            for (int k = 0; k < 3; ++k)
                positions.push_back(pool.vertices[range.vertexOffset + pool.indices[range.firstIndex + i]].position[k]);
    return positions;
}

class ModelKindTest : public testing::TestWithParam<const char*> {};

TEST_P(ModelKindTest, BuildsGeometryAndJointsTheSameForEachVariant) {
    const Scene scene = sceneOfModel(std::filesystem::path(PLANTFIELD_DATA_DIR) / GetParam(), 2);
    const PlantModelPool first = buildPlantModels(scene);
    const PlantModelPool again = buildPlantModels(scene);
    ASSERT_EQ(first.models.size(), 2u);
    ASSERT_EQ(again.models.size(), 2u);
    for (size_t m = 0; m < first.models.size(); ++m) {
        EXPECT_GT(first.models[m].meshes[LOD_FULL][DRAW_BARK].indexCount, 0u) << m;
        EXPECT_GT(first.models[m].joints, 1u) << m;
        EXPECT_FALSE(positionsOf(first, first.models[m]).empty()) << m;
        EXPECT_EQ(positionsOf(first, first.models[m]), positionsOf(again, again.models[m])) << m;
        // Scaled so the full-detail mesh's top is the species' height, as an
        // L-system's plant (the culling box also holds LOD1's enlarged leaves).
        const std::vector<float> positions = positionsOf(first, first.models[m]);
        float top = std::numeric_limits<float>::lowest();
        for (size_t i = 1; i < positions.size(); i += 3) top = std::max(top, positions[i]);
        EXPECT_NEAR(top, 5.0f, 1e-3f) << m;
        EXPECT_GE(first.models[m].gpu.boxMax.y, top) << m;
    }
    EXPECT_TRUE(first.warnings.empty()) << first.warnings;
}

INSTANTIATE_TEST_SUITE_P(Scene, ModelKindTest,
                         testing::Values("ramified/oak.ram.json", "ramified/pine.ram.json",
                                         "components/coconut_palm.comp.json", "components/sunflower.comp.json"),
                         [](const testing::TestParamInfo<const char*>& info) {
                             std::string name = std::filesystem::path(info.param).filename().string();
                             for (char& c : name)
                                 if (c == '.') c = '_';
                             return name;
                         });

TEST(ModelSpecies, EachVariantOfATreeTypeIsADifferentTree) {
    const PlantModelPool pool = buildPlantModels(sceneOfModel(PLANTFIELD_DATA_DIR "/ramified/oak.ram.json", 3));
    ASSERT_EQ(pool.models.size(), 3u);
    EXPECT_NE(positionsOf(pool, pool.models[0]), positionsOf(pool, pool.models[1]));
    EXPECT_NE(positionsOf(pool, pool.models[1]), positionsOf(pool, pool.models[2]));
    EXPECT_NE(positionsOf(pool, pool.models[0]), positionsOf(pool, pool.models[2]));
}

// A malformed model file fails when the models are built, naming the species
// and the fault's file:line:column.
void expectLocatedModelError(const std::string& name, const std::string& text, const std::string& at) {
    const std::filesystem::path model = test::writeFile(name, text);
    try {
        buildPlantModels(sceneOfModel(model, 1));
        FAIL() << "a malformed " << name << " built";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("species 'probe'"), std::string::npos) << what;
        EXPECT_NE(what.find(model.string() + ":" + test::lineColumnOf(text, at) + ":"), std::string::npos) << what;
    }
}

TEST(ModelSpecies, AMalformedTreeTypeNamesSpeciesFileLineAndColumn) {
    expectLocatedModelError("bad.ram.json", "{\n  \"balance\": 50,\n  \"depth\": \"seven\"\n}", "\"seven\"");
}

TEST(ModelSpecies, AMalformedComponentPlantNamesSpeciesFileLineAndColumn) {
    expectLocatedModelError(
        "bad.comp.json",
        "{\n  \"root\": \"stalk\",\n  \"components\": {\n    \"stalk\": { \"kind\": \"stme\" }\n  }\n}", "\"stme\"");
}

} // namespace
} // namespace pf
