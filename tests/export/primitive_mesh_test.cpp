#include "lsystem/mesh/primitive_mesh.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "sample_plants.h"

namespace {

using lsys::MeshDetail;
using lsys::TriangleMesh;

double signedAreaAlong(const TriangleMesh& mesh, glm::vec3 normal) {
    double area = 0.0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                        c = mesh.positions[mesh.indices[t + 2]];
        area += 0.5 * glm::dot(glm::cross(b - a, c - a), normal);
    }
    return area;
}

void expectWellFormed(const TriangleMesh& mesh) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertexCount());
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

// Closed, outward-wound meshes enclose a positive volume (divergence theorem).
double enclosedVolume(const TriangleMesh& mesh) {
    double volume = 0.0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3)
        volume += glm::dot(mesh.positions[mesh.indices[t]],
                           glm::cross(mesh.positions[mesh.indices[t + 1]], mesh.positions[mesh.indices[t + 2]])) /
                  6.0;
    return volume;
}

TEST(ExportSegmentMesh, CountsWithAndWithoutCaps) {
    MeshDetail detail;
    detail.segmentSides = 8;
    const TriangleMesh capped = lsys::segmentMesh(2.0f, 0.5f, 0.25f, detail);
    expectWellFormed(capped);
    EXPECT_EQ(capped.vertexCount(), 36u);   // 2 rings of 9 (seam doubled) + 2 caps of 1 + 8
    EXPECT_EQ(capped.triangleCount(), 32u); // 16 on the sides + 8 per cap
    detail.segmentCaps = false;
    const TriangleMesh open = lsys::segmentMesh(2.0f, 0.5f, 0.25f, detail);
    EXPECT_EQ(open.vertexCount(), 18u);
    EXPECT_EQ(open.triangleCount(), 16u);
}

TEST(ExportSegmentMesh, FrustumShapeAndWinding) {
    MeshDetail detail;
    detail.segmentSides = 64;
    const TriangleMesh mesh = lsys::segmentMesh(2.0f, 0.5f, 0.25f, detail);
    for (const glm::vec3& p : mesh.positions) {
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LE(p.y, 2.0f);
        const float radius = 0.5f - 0.125f * p.y;
        ASSERT_LE(std::hypot(p.x, p.z), radius + 1e-5f);
    }
    // A frustum's volume is πh(R² + Rr + r²)/3; 64 sides come within 0.5 %.
    const double exact = M_PI * 2.0 * (0.25 + 0.125 + 0.0625) / 3.0;
    EXPECT_NEAR(enclosedVolume(mesh), exact, 0.005 * exact);
    // A cone's side normals lean towards the narrow end.
    EXPECT_GT(mesh.normals[0].y, 0.0f);
}

TEST(ExportSegmentMesh, ConeTipKeepsTopology) {
    const TriangleMesh cone = lsys::segmentMesh(1.0f, 0.3f, 0.0f, MeshDetail{});
    EXPECT_EQ(cone.vertexCount(), 36u);
    EXPECT_EQ(cone.triangleCount(), 32u);
    expectWellFormed(cone);
}

TEST(ExportSphereMesh, CountsAndRadius) {
    MeshDetail detail;
    detail.sphereSlices = 12;
    detail.sphereStacks = 8;
    const TriangleMesh sphere = lsys::sphereMesh(0.5f, detail);
    expectWellFormed(sphere);
    EXPECT_EQ(sphere.vertexCount(), 117u);   // 13 × 9
    EXPECT_EQ(sphere.triangleCount(), 168u); // 2 × 12 × 7
    for (const glm::vec3& p : sphere.positions) ASSERT_NEAR(glm::length(p), 0.5f, 1e-6f);
    EXPECT_GT(enclosedVolume(sphere), 0.8 * 4.0 / 3.0 * M_PI * 0.125);
}

TEST(ExportPolygonMesh, NonConvexOutlineIsTriangulatedInsideIt) {
    // An L in a tilted plane: a fan from corner 0 would cover area outside it.
    const glm::quat tilt = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    const std::vector<glm::vec2> corners{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (size_t start = 0; start < corners.size(); ++start) {
        std::vector<glm::vec3> outline;
        for (size_t i = 0; i < corners.size(); ++i) {
            const glm::vec2 c = corners[(start + i) % corners.size()];
            outline.push_back(tilt * glm::vec3(c.x, c.y, 0.0f) + glm::vec3(5, 1, -2));
        }
        const TriangleMesh mesh = lsys::polygonMesh(outline);
        expectWellFormed(mesh);
        EXPECT_EQ(mesh.vertexCount(), 6u);
        EXPECT_EQ(mesh.triangleCount(), 4u);
        const glm::vec3 normal = tilt * glm::vec3(0, 0, 1);
        EXPECT_NEAR(glm::dot(mesh.normals[0], normal), 1.0f, 1e-5f);
        // Every triangle faces the normal and together they cover exactly
        // the L's area: no overlap, nothing outside.
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
            TriangleMesh one{
                mesh.positions, mesh.normals, mesh.uvs, {mesh.indices.begin() + t, mesh.indices.begin() + t + 3}};
            EXPECT_GT(signedAreaAlong(one, normal), 0.0);
        }
        EXPECT_NEAR(signedAreaAlong(mesh, normal), 3.0, 1e-5);
    }
}

TEST(ExportPolygonMesh, ClockwiseOutlineFacesTheOtherWay) {
    const TriangleMesh mesh = lsys::polygonMesh({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}});
    EXPECT_EQ(mesh.triangleCount(), 2u);
    EXPECT_NEAR(mesh.normals[0].z, -1.0f, 1e-6f);
    EXPECT_NEAR(signedAreaAlong(mesh, {0, 0, -1}), 1.0, 1e-6);
}

TEST(ExportPolygonMesh, DegenerateOutlinesGiveNothing) {
    EXPECT_EQ(lsys::polygonMesh({}).vertexCount(), 0u);
    EXPECT_EQ(lsys::polygonMesh({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}}).vertexCount(), 0u);
    EXPECT_EQ(lsys::polygonMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).vertexCount(), 0u); // collinear
    // Repeated points (a turtle `.` twice in place) are dropped, not triangulated.
    EXPECT_EQ(lsys::polygonMesh({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}}).triangleCount(), 1u);
}

TEST(ExportSurfaceMesh, ComputesMissingNormals) {
    const lsys::SurfaceMesh leaf{"leaf", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {}, {0, 1, 2}};
    const TriangleMesh mesh = lsys::surfaceMesh(leaf);
    expectWellFormed(mesh);
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST(ExportSegmentChains, StemContinuesThroughTheBranchPoint) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    const std::vector<lsys::SegmentChain> chains = lsys::segmentChains(plant);
    ASSERT_EQ(chains.size(), 2u); // segment 4 has no width: in no chain
    EXPECT_EQ(chains[0].primitives, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(chains[1].primitives, (std::vector<uint32_t>{3}));
}

TEST(ExportSegmentChains, MaterialChangeStartsANewChain) {
    lsys::PlantAsset plant = plantfield::test::samplePlant();
    plant.materials.push_back({"dark bark"});
    plant.primitives[1].material = 2;
    const std::vector<lsys::SegmentChain> chains = lsys::segmentChains(plant);
    ASSERT_EQ(chains.size(), 3u);
    EXPECT_EQ(chains[0].primitives,
              (std::vector<uint32_t>{0, 3})); // the branch is now the straightest same-material child
    EXPECT_EQ(chains[1].primitives, (std::vector<uint32_t>{1}));
    EXPECT_EQ(chains[2].primitives, (std::vector<uint32_t>{2}));
}

TEST(ExportGeneralizedCylinder, CountsSharedRings) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    MeshDetail detail;
    detail.segmentSides = 8;
    const TriangleMesh stem = lsys::generalizedCylinderMesh(plant, {{0, 1, 2}}, detail);
    expectWellFormed(stem);
    EXPECT_EQ(stem.vertexCount(), 54u);   // 4 rings of 9 + 2 caps of 9
    EXPECT_EQ(stem.triangleCount(), 64u); // 3 × 16 + 2 × 8
    detail.segmentCaps = false;
    EXPECT_EQ(lsys::generalizedCylinderMesh(plant, {{0, 1, 2}}, detail).vertexCount(), 36u);
}

TEST(ExportGeneralizedCylinder, InnerRingsLieHalfwayAndKeepTheThickness) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    MeshDetail detail;
    detail.segmentSides = 16;
    detail.segmentCaps = false;
    const TriangleMesh stem = lsys::generalizedCylinderMesh(plant, {{0, 1, 2}}, detail);
    const auto headingOf = [&](size_t i) { return plant.primitives[i].frame.rotation * glm::vec3(0, 1, 0); };
    // Ring 1 joins segments 0 and 1 at the tip of 0.
    const glm::vec3 centre = plantfield::test::segmentTip(plant, 0);
    const glm::vec3 in = headingOf(0), out = headingOf(1);
    const glm::vec3 mitre = glm::normalize(in + out);
    const float radius = 0.5f * (plant.primitives[0].endRadius + plant.primitives[1].startRadius);
    for (uint32_t j = 17; j < 34; ++j) {
        const glm::vec3 offset = stem.positions[j] - centre;
        ASSERT_NEAR(glm::dot(offset, mitre), 0.0f, 1e-5f);
        // Seen along either segment, the ring is a circle of the radius: no
        // gap, no pinch.
        EXPECT_NEAR(glm::length(offset - glm::dot(offset, in) * in), radius, 1e-5f);
        EXPECT_NEAR(glm::length(offset - glm::dot(offset, out) * out), radius, 1e-5f);
    }
    // The first and last rings are square to their segments.
    for (uint32_t j = 0; j < 17; ++j) EXPECT_NEAR(glm::dot(stem.positions[j], in), 0.0f, 1e-6f);
}

TEST(ExportGeneralizedCylinder, SingleSegmentMatchesTheSegmentMesh) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    const lsys::Primitive& branch = plant.primitives[3];
    const TriangleMesh tube = lsys::generalizedCylinderMesh(plant, {{3}}, MeshDetail{});
    TriangleMesh segment;
    segment.append(lsys::segmentMesh(branch.length, branch.startRadius, branch.endRadius, MeshDetail{}),
                   lsys::frameMatrix(branch.frame));
    ASSERT_EQ(tube.vertexCount(), segment.vertexCount());
    ASSERT_EQ(tube.indices, segment.indices);
    for (size_t i = 0; i < tube.positions.size(); ++i)
        EXPECT_NEAR(glm::distance(tube.positions[i], segment.positions[i]), 0.0f, 1e-6f);
}

TEST(ExportGeneralizedCylinder, WindingStemStaysOneTubeOfSteadyThickness) {
    const lsys::PlantAsset helix = plantfield::test::helixPlant(60);
    const std::vector<lsys::SegmentChain> chains = lsys::segmentChains(helix);
    ASSERT_EQ(chains.size(), 1u);
    ASSERT_EQ(chains[0].primitives.size(), 60u);
    MeshDetail detail;
    detail.segmentCaps = false;
    const TriangleMesh tube = lsys::generalizedCylinderMesh(helix, chains[0], detail);
    expectWellFormed(tube);
    EXPECT_EQ(tube.vertexCount(), 61u * 9u);
    EXPECT_EQ(tube.triangleCount(), 60u * 16u);
    // Every ring, seen along the segment it ends, is a circle of its radius
    // (the stretch exactly undoes the mitre's tilt).
    for (uint32_t ring = 1; ring <= 60; ++ring) {
        const lsys::Primitive& in = helix.primitives[ring - 1];
        const glm::vec3 axis = in.frame.rotation * glm::vec3(0, 1, 0);
        const glm::vec3 centre = plantfield::test::segmentTip(helix, ring - 1);
        const float radius = ring < 60 ? 0.5f * (in.endRadius + helix.primitives[ring].startRadius) : in.endRadius;
        for (uint32_t j = 0; j <= detail.segmentSides; ++j) {
            const glm::vec3 offset = tube.positions[ring * 9 + j] - centre;
            ASSERT_NEAR(glm::length(offset - glm::dot(offset, axis) * axis), radius, 1e-5f) << ring << ' ' << j;
        }
    }
}

TEST(ExportMeshesByMaterial, BakesEveryDrawablePrimitive) {
    const lsys::PlantAsset plant = plantfield::test::samplePlant();
    const auto frusta = lsys::meshesByMaterial(plant, lsys::SegmentGeometry::Frusta, MeshDetail{});
    ASSERT_EQ(frusta.size(), 2u);
    EXPECT_EQ(frusta[0].vertexCount(), 4 * 36u + 117u); // 4 drawable segments and the sphere
    EXPECT_EQ(frusta[0].triangleCount(), 4 * 32u + 168u);
    EXPECT_EQ(frusta[1].vertexCount(), 2 * 4u + 6u); // 2 leaves and the polygon
    EXPECT_EQ(frusta[1].triangleCount(), 2 * 2u + 4u);
    const auto tubes = lsys::meshesByMaterial(plant, lsys::SegmentGeometry::GeneralizedCylinders, MeshDetail{});
    EXPECT_EQ(tubes[0].vertexCount(), 54u + 36u + 117u);
    EXPECT_EQ(tubes[0].triangleCount(), 64u + 32u + 168u);
    EXPECT_EQ(tubes[1].vertexCount(), frusta[1].vertexCount());
}

} // namespace
