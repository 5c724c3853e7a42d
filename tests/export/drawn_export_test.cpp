// The drawn form of the flat export (lsystem/mesh/drawn_mesh.h): foliage segments
// come out as the renderer's flat ribbons, leaf cards as the leaf outline its
// shader cuts (shaders/shared/leaf_outline.h), and the outline mesh covers what the
// shader keeps.
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/rewriting/plant_from_grammar.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "../lsystem/test_support.h"
#include "gltf_reading.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "sample_plants.h"
#include "shaders/shared/leaf_outline.h"

namespace {

namespace fs = std::filesystem;
using plantfield::test::loadGltf;

using DrawnExport = plantfield::test::ExportDirTest;

lsys::PlantAsset plantOfFile(const std::string& file) {
    const lsys::Grammar grammar = lsys::test::loadOk(file);
    const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(lsys::test::dataPath(file)));
    return lsys::plantFromGrammar(grammar, lsys::derive(grammar, {}), surfaces);
}

// The POSITION values of a glTF mesh's (only) primitive.
std::vector<glm::vec3> positionsOf(const tinygltf::Model& model, const tinygltf::Mesh& mesh) {
    const tinygltf::Accessor& accessor = model.accessors.at(size_t(mesh.primitives.at(0).attributes.at("POSITION")));
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
    const auto* data = reinterpret_cast<const float*>(model.buffers.at(size_t(view.buffer)).data.data() +
                                                      view.byteOffset + accessor.byteOffset);
    std::vector<glm::vec3> positions;
    for (size_t i = 0; i < accessor.count; ++i) positions.emplace_back(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    return positions;
}

// data/plants/spruce.lsys draws its needle sprays with a two-sided material:
// the renderer's ribbons, one flat quad a segment, as wide as the segment
// (at least the plant's minimum ribbon width), where the turtle's geometry
// has a cylinder a segment.
TEST_F(DrawnExport, SpruceNeedlesAreTheRenderersRibbons) {
    const lsys::PlantAsset spruce = plantOfFile("plants/spruce.lsys");
    lsys::exportPlant(spruce, dir / "spruce.glb");
    const tinygltf::Model model = loadGltf(dir / "spruce.glb");
    const float minWidth = lsys::drawnScaleOf(spruce).minRibbonWidth;
    std::vector<const lsys::Primitive*> needles;
    for (const lsys::Primitive& p : spruce.primitives)
        if (p.kind == lsys::PrimitiveKind::Segment && lsys::isDrawable(p) && spruce.materials[p.material].twoSided)
            needles.push_back(&p);
    ASSERT_GT(needles.size(), 100u);

    size_t ribbons = 0;
    for (const tinygltf::Mesh& mesh : model.meshes) {
        const int material = mesh.primitives.at(0).material;
        if (!spruce.materials.at(size_t(material)).twoSided) continue;
        SCOPED_TRACE(mesh.name);
        EXPECT_TRUE(model.materials.at(size_t(material)).doubleSided);
        const std::vector<glm::vec3> v = positionsOf(model, mesh);
        ASSERT_EQ(v.size() % 4, 0u) << "not quads";
        for (size_t q = 0; q < v.size(); q += 4, ++ribbons) {
            const glm::vec3 across = v[q + 1] - v[q], along = v[q + 3] - v[q];
            const glm::vec3 normal = glm::normalize(glm::cross(across, along));
            const float size = glm::length(along) + glm::length(across);
            ASSERT_LE(std::abs(glm::dot(v[q + 2] - v[q], normal)), 1e-4f * size) << "ribbon " << q / 4 << " not flat";
            // Its base is centred on a needle's base, as wide as the renderer makes it.
            const glm::vec3 base = 0.5f * (v[q] + v[q + 1]);
            const float width = glm::length(across);
            const bool matches = std::any_of(needles.begin(), needles.end(), [&](const lsys::Primitive* p) {
                const float expected = std::max(2.0f * p->startRadius, minWidth);
                return glm::length(p->frame.position - base) <= 1e-5f && std::abs(width - expected) <= 1e-4f * expected;
            });
            ASSERT_TRUE(matches) << "ribbon " << q / 4 << " of width " << width << " matches no needle";
        }
    }
    EXPECT_EQ(ribbons, needles.size());
}

// Leaf cards come out as the leaf outline: kLeafOutlineRows·2 vertices a
// leaf, every one inside its card, on the surface's plane.
TEST_F(DrawnExport, LeafCardsAreTheirOutlines) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    lsys::exportPlant(plant, dir / "plant.glb");
    const tinygltf::Model model = loadGltf(dir / "plant.glb");
    ASSERT_EQ(model.meshes.size(), 2u);
    // Material 1: two leaves and the six-point polygon.
    const std::vector<glm::vec3> foliage = positionsOf(model, model.meshes[1]);
    EXPECT_EQ(foliage.size(), 2 * lsys::leafOutline().uvs.size() + 6);
    EXPECT_TRUE(model.materials[1].doubleSided);
}

// The outline mesh lies inside the card, winds counter-clockwise, and its
// area is the area where the shader's leafShape is above 0, to 2 %: it leaves
// out the serration (±0.018 of the card's width, about as much cut as added)
// and the petiole, and cuts the curve into kLeafOutlineRows chords.
TEST(LeafOutline, CoversWhatTheShaderKeeps) {
    const lsys::LeafOutline& outline = lsys::leafOutline();
    ASSERT_EQ(outline.uvs.size(), 2 * lsys::kLeafOutlineRows);
    for (const glm::vec2& uv : outline.uvs) {
        EXPECT_GE(uv.x, 0.0f);
        EXPECT_LE(uv.x, 1.0f);
        EXPECT_GE(uv.y, 0.0f);
        EXPECT_LE(uv.y, 1.0f);
    }
    double meshArea = 0.0;
    for (size_t t = 0; t < outline.indices.size(); t += 3) {
        const glm::vec2 a = outline.uvs[outline.indices[t]], b = outline.uvs[outline.indices[t + 1]],
                        c = outline.uvs[outline.indices[t + 2]];
        const double twice = double(b.x - a.x) * (c.y - a.y) - double(b.y - a.y) * (c.x - a.x);
        EXPECT_GE(twice, 0.0) << "triangle " << t / 3 << " winds clockwise";
        meshArea += 0.5 * twice;
    }
    constexpr int kCells = 1000;
    double kept = 0.0;
    for (int i = 0; i < kCells; ++i)
        for (int j = 0; j < kCells; ++j)
            kept += leaf_outline::shape((i + 0.5) / kCells, (j + 0.5) / kCells) > 0.0 ? 1.0 : 0.0;
    const double shaderArea = kept / (double(kCells) * kCells);
    EXPECT_GT(shaderArea, 0.3); // a leaf, not a sliver
    EXPECT_NEAR(meshArea, shaderArea, 0.02 * shaderArea);
}

} // namespace
