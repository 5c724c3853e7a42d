// Every plant in data/plants (dialect files in data/plants/dialects included)
// interprets into a PlantAsset with finite numbers everywhere.

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "lsystem/dialects/dialect.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/vlab/object.h"
#include "turtle_test_support.h"

namespace lsys::test {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const Frame& f) {
    return finite(f.position) && std::isfinite(f.rotation.w) &&
           finite(glm::vec3(f.rotation.x, f.rotation.y, f.rotation.z));
}

void expectFinite(const PlantAsset& plant) {
    for (const Primitive& p : plant.primitives) {
        ASSERT_TRUE(finite(p.frame) && std::isfinite(p.length) && std::isfinite(p.startRadius) &&
                    std::isfinite(p.endRadius));
        ASSERT_LT(p.material, plant.materials.size());
    }
    for (const Joint& j : plant.joints)
        ASSERT_TRUE(finite(j.rest) && std::isfinite(j.length) && std::isfinite(j.startRadius) &&
                    std::isfinite(j.stiffness));
    for (const PolygonShape& polygon : plant.polygons)
        for (const glm::vec3& v : polygon.outline) ASSERT_TRUE(finite(v));
    if (!plant.primitives.empty()) {
        ASSERT_FALSE(plant.bounds.empty());
        ASSERT_TRUE(finite(plant.bounds.min) && finite(plant.bounds.max));
    }
}

TEST(LsysTurtleDataFiles, EveryPlantInterpretsWithoutNaN) {
    const std::filesystem::path root = dataPath("plants");
    const std::vector<std::filesystem::path> files = vlab::findPlants(root);
    ASSERT_GE(files.size(), 20u);
    size_t drawn = 0;
    for (const std::filesystem::path& file : files) {
        SCOPED_TRACE(file.string());
        const vlab::PlantFile loaded = vlab::loadPlant(file);
        const ParseResult& parsed = loaded.parsed;
        ASSERT_TRUE(parsed.ok());
        const ModuleString derived = derive(parsed.grammar);
        if (derived.size() > 2'000'000) continue; // the benchmark-sized systems
        const SurfaceLibrary surfaces(meshDirectoriesFor(file));
        const PlantAsset plant = plantFromGrammar(parsed.grammar, derived, surfaces);
        expectFinite(plant);
        drawn += !plant.primitives.empty();
    }
    EXPECT_GE(drawn, 15u);
}

// The first example of Robbins 1998 draws its leaves as { +F -F -F } triangles.
TEST(LsysTurtleDataFiles, RobbinsLeavesAreTriangles) {
    for (const char* file :
         {"plants/dialects/robbins_first_example.robbins", "plants/dialects/robbins_first_example.lsys"}) {
        SCOPED_TRACE(file);
        ParseResult parsed = loadDialectFile(dataPath(file));
        ASSERT_TRUE(parsed.ok());
        DeriveOptions options;
        options.steps = 4;
        const PlantAsset plant = plantFromGrammar(parsed.grammar, derive(parsed.grammar, options));
        ASSERT_GT(plant.polygons.size(), 10u);
        for (const PolygonShape& leaf : plant.polygons) ASSERT_EQ(leaf.outline.size(), 3u);
        EXPECT_TRUE(plant.materials.at(0).twoSided); // the leaves share the bark's material
    }
}

} // namespace
} // namespace lsys::test
