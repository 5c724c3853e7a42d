// Component plants built into PlantAssets: pinned counts for a small graph,
// the skeleton as one tree with stems as joints, determinism, and the
// example species in data/components.
#include "component_test_support.h"
#include "lsystem/components/component_graph.h"
#include "lsystem/mesh/primitive_mesh.h"

#include <gtest/gtest.h>

namespace lsys::components {
namespace {

// An axis of 4 segments with 3 branches of 2 segments, a leaf on each
// branch's tip and a whorl of 4 leaves on the axis's tip.
constexpr const char* kSmallPlant = R"({
  "seed": 5,
  "root": "plant",
  "components": {
    "axis": { "kind": "stem", "length": 1, "radius": [0.05, 0.01], "detail": 4, "children": ["bud"] },
    "plant": { "kind": "tree", "stem": "axis", "count": 3, "start": 0.25, "end": 0.75, "angle": 60,
               "scale_variation": 0.3, "angle_variation": 10, "children": ["branch"] },
    "branch": { "kind": "stem", "length": 0.4, "radius": 0.01, "detail": 2, "children": ["leaf"] },
    "leaf": { "kind": "leaf", "length": 0.1, "detail": 5 },
    "bud": { "kind": "radial", "count": 4, "node_angle": 30, "children": ["leaf"] }
  }
})";

PlantAsset smallPlant() { return loadComponentPlant(test::writeComponentFile("small.comp.json", kSmallPlant)); }

size_t countKind(const PlantAsset& asset, PrimitiveKind kind) {
    size_t n = 0;
    for (const Primitive& p : asset.primitives) n += p.kind == kind;
    return n;
}

uint64_t bakedVertices(const PlantAsset& asset, SegmentGeometry geometry) {
    uint64_t vertices = 0;
    for (const TriangleMesh& mesh : meshesByMaterial(asset, geometry, MeshDetail{})) vertices += mesh.vertexCount();
    return vertices;
}

TEST(ComponentPlant, SmallGraphHasPinnedCounts) {
    const PlantAsset asset = smallPlant();
    EXPECT_EQ(asset.primitives.size(), 17u); // 4 + 3·(2 + 1) + 4
    EXPECT_EQ(countKind(asset, PrimitiveKind::Segment), 10u);
    EXPECT_EQ(countKind(asset, PrimitiveKind::Polygon), 7u);
    EXPECT_EQ(asset.joints.size(), 10u);
    // The default blade sampled at 5 points, mirrored without repeating the midrib's ends: 8 points.
    for (const PolygonShape& polygon : asset.polygons) EXPECT_EQ(polygon.outline.size(), 8u);
    // Generalised cylinders: chains of 4 and 3 × 2 segments, 9 vertices a ring, capped; 7 blades of 8.
    EXPECT_EQ(bakedVertices(asset, SegmentGeometry::GeneralizedCylinders), 5u * 9 + 18 + 3 * (3 * 9 + 18) + 7 * 8);
    // Frusta: 10 segments of 2·9 side and 2·9 cap vertices.
    EXPECT_EQ(bakedVertices(asset, SegmentGeometry::Frusta), 10u * 36 + 7 * 8);
}

TEST(ComponentPlant, CountsMatchWhatIsDrawn) {
    const ComponentGraph graph = readComponentGraph(test::writeComponentFile("counted.comp.json", kSmallPlant));
    const ComponentCounts counts = countComponentPlant(graph);
    // Components by name: axis, branch, bud, leaf, plant.
    EXPECT_EQ(counts.draws, (std::vector<uint64_t>{1, 3, 1, 7, 1}));
    EXPECT_EQ(counts.instances, 13u);
    EXPECT_EQ(counts.primitives, buildComponentPlant(graph).primitives.size());
}

TEST(ComponentPlant, MemoryBudgetIsCheckedBeforeDrawing) {
    const ComponentGraph graph = readComponentGraph(test::writeComponentFile("memory.comp.json", kSmallPlant));
    EXPECT_GT(countComponentPlant(graph).bytes, 1000u);
    EXPECT_THROW(buildComponentPlant(graph, MemoryBudget{1000}), MemoryBudgetError);
    EXPECT_NO_THROW(buildComponentPlant(graph, MemoryBudget{countComponentPlant(graph).bytes}));
}

TEST(ComponentPlant, StemsAreJointsOfOneSkeleton) {
    const PlantAsset asset = smallPlant();
    size_t roots = 0;
    for (size_t j = 0; j < asset.joints.size(); ++j) {
        roots += asset.joints[j].parent < 0;
        EXPECT_LT(asset.joints[j].parent, int32_t(j)) << "joint " << j << " comes before its parent";
    }
    EXPECT_EQ(roots, 1u);
    for (const Primitive& p : asset.primitives) {
        EXPECT_GE(p.joint, 0) << "every primitive moves with a stem";
        if (p.kind == PrimitiveKind::Segment) {
            EXPECT_EQ(asset.joints[p.joint].length, p.length);
        }
    }
    // Axis joints 0-3; each branch's first joint grows on the axis segment
    // holding its node (u = 0.25, 0.5, 0.75 of 4 segments), at that point.
    const int32_t expectedParents[] = {1, 2, 3};
    for (int b = 0; b < 3; ++b) {
        const Joint& first = asset.joints[4 + 2 * b];
        EXPECT_EQ(first.parent, expectedParents[b]);
        const Joint& axis = asset.joints[first.parent];
        const glm::vec3 axisHeading = axis.rest.rotation * glm::vec3(0, 1, 0);
        const glm::vec3 offset = first.rest.position - axis.rest.position;
        EXPECT_NEAR(glm::length(offset - axisHeading * glm::dot(offset, axisHeading)), 0.0f, 1e-5f);
    }
    // The axis and each branch are one chain each: drawn as generalised cylinders.
    EXPECT_EQ(segmentChains(asset).size(), 4u);
}

TEST(ComponentPlant, SameFileSamePlantAndTheSeedChangesIt) {
    const PlantAsset a = smallPlant(), b = smallPlant();
    EXPECT_TRUE(a.primitives == b.primitives);
    std::string reseeded = kSmallPlant;
    reseeded.replace(reseeded.find("\"seed\": 5"), 9, "\"seed\": 6");
    const PlantAsset c = loadComponentPlant(test::writeComponentFile("reseeded.comp.json", reseeded));
    ASSERT_EQ(a.primitives.size(), c.primitives.size());
    EXPECT_FALSE(a.primitives == c.primitives);
}

TEST(ComponentPlant, MaterialsComeFromTheFileOverThePalette) {
    const PlantAsset asset = loadComponentPlant(test::writeComponentFile("materials.comp.json", R"({
  "root": "s",
  "materials": { "bark": { "albedo": [0.1, 0.2, 0.3] }, "petal": { "albedo": [1, 1, 0] }, "sepal": { "albedo": [0, 0.5, 0] } },
  "components": {
    "s": { "kind": "stem", "detail": 1, "children": ["p"] },
    "p": { "kind": "leaf", "material": "sepal" }
  }
})"));
    ASSERT_EQ(asset.primitives.size(), 2u);
    const Material& bark = asset.materials.at(asset.primitives[0].material);
    EXPECT_EQ(bark.name, "bark");
    EXPECT_EQ(bark.albedo, glm::vec3(0.1f, 0.2f, 0.3f));
    const Material& sepal = asset.materials.at(asset.primitives[1].material);
    EXPECT_EQ(sepal.name, "sepal");
    EXPECT_TRUE(sepal.twoSided); // a blade is seen from both sides
}

TEST(ComponentPlant, HiddenTreeStemDrawsNothingButCarriesItsBranches) {
    const PlantAsset asset = loadComponentPlant(test::writeComponentFile("hidden.comp.json", R"({
  "root": "t",
  "components": {
    "axis": { "kind": "stem", "detail": 3 },
    "t": { "kind": "tree", "stem": "axis", "stem_visible": false, "count": 2, "children": ["twig"] },
    "twig": { "kind": "stem", "detail": 2 }
  }
})"));
    EXPECT_EQ(asset.joints.size(), 4u); // the two twigs only
    EXPECT_EQ(asset.joints[0].parent, -1);
    EXPECT_EQ(asset.joints[2].parent, -1);
}

struct Species {
    const char* file;
    float minHeight, maxHeight;
    size_t minBlades;
};

class ExampleSpecies : public testing::TestWithParam<Species> {};

TEST_P(ExampleSpecies, BuildsAPlantOfItsSize) {
    const Species& species = GetParam();
    const PlantAsset asset =
        loadComponentPlant(std::filesystem::path(PLANTFIELD_DATA_DIR) / "components" / species.file);
    EXPECT_GE(countKind(asset, PrimitiveKind::Polygon), species.minBlades);
    EXPECT_NEAR(asset.bounds.min.y, 0.0f, 0.05f);
    EXPECT_GT(asset.bounds.max.y, species.minHeight);
    EXPECT_LT(asset.bounds.max.y, species.maxHeight);
    size_t roots = 0;
    for (const Joint& joint : asset.joints) roots += joint.parent < 0;
    EXPECT_EQ(roots, 1u);
}

INSTANTIATE_TEST_SUITE_P(Data, ExampleSpecies,
                         testing::Values(Species{"broadleaf_sapling.comp.json", 2.5f, 5.0f, 500},
                                         Species{"coconut_palm.comp.json", 5.0f, 9.0f, 500},
                                         Species{"sunflower.comp.json", 1.5f, 2.5f, 40}),
                         [](const auto& info) {
                             std::string name = info.param.file;
                             return name.substr(0, name.find('.'));
                         });

TEST(ComponentPlant, BenchmarkTreeHasAThousandLeaves) {
    // The tree docs/BENCHMARKS.md times: 20 branches of 50 leaves.
    const PlantAsset asset =
        loadComponentPlant(std::filesystem::path(PLANTFIELD_COMPONENT_TEST_DIR) / "thousand_leaves.comp.json");
    EXPECT_EQ(countKind(asset, PrimitiveKind::Polygon), 1000u);
}

} // namespace
} // namespace lsys::components
