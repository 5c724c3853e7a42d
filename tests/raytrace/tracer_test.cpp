// The tracers: primitives placed in a hand-made plant against analytic hits,
// and the hierarchical tracer against the flat one on plant files (the same
// hits for the same rays, the Calgary b-grammar thesis' ch. 7 comparison).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "../instance_graph/instance_graph_test_support.h"
#include "lsystem/raytrace/flat_tracer.h"
#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/turtle/turtle.h"
#include "seeded_rays.h"

namespace lsys::test {
namespace {

// A quarter turn about +Z: local +Y (the heading) goes to −X.
const glm::quat kHeadingMinusX = glm::angleAxis(std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1));

PlantAsset handMadePlant() {
    PlantAsset plant;
    plant.materials.resize(4);
    // A cylinder from (1, 2, 3) along −X, length 2, radius 0.5: material 1.
    plant.primitives.push_back(
        {{glm::vec3(1, 2, 3), kHeadingMinusX}, PrimitiveKind::Segment, 1, -1, 0, 2.0f, 0.5f, 0.5f});
    // A sphere of radius 0.5 at (0, 10, 0): material 2.
    plant.primitives.push_back({Frame{glm::vec3(0, 10, 0)}, PrimitiveKind::Sphere, 2, -1, 0, 0.0f, 0.5f, 0.0f});
    // A unit square surface on local x, y ∈ [0, 1], scaled by 3 and placed at (20, 0, 0): material 3.
    SurfaceMesh square;
    square.name = "square";
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.indices = {0, 1, 2, 0, 2, 3};
    plant.surfaces.push_back(square);
    plant.primitives.push_back({Frame{glm::vec3(20, 0, 0)}, PrimitiveKind::Surface, 3, -1, 0, 3.0f, 0.0f, 0.0f});
    // A polygon at z = −5 in plant space; its frame is only where it began.
    plant.polygons.push_back({{{-1, -1, -5}, {1, -1, -5}, {1, 3, -5}, {-1, 3, -5}}});
    plant.primitives.push_back({{glm::vec3(7, 7, 7), kHeadingMinusX}, PrimitiveKind::Polygon, 0, -1, 0, 0, 0, 0});
    return plant;
}

void expectHit(const std::optional<Hit>& hit, float t, uint32_t primitive, glm::vec3 normal) {
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, t, 1e-5f);
    EXPECT_EQ(hit->primitive, primitive);
    EXPECT_NEAR(glm::distance(hit->normal, normal), 0.0f, 1e-5f);
}

TEST(FlatTracer, PlacedPrimitivesGiveAnalyticHits) {
    const PlantAsset plant = handMadePlant();
    const FlatTracer tracer = buildFlatTracer(plant);
    // Down onto the cylinder's top, halfway along it (x = 0).
    expectHit(trace(tracer, Ray{glm::vec3(0, 5, 3), glm::vec3(0, -1, 0)}, HitQuery::Closest), 2.5f, 0, {0, 1, 0});
    // Along its axis from +X: its base cap at x = 1, facing +X (against the heading).
    expectHit(trace(tracer, Ray{glm::vec3(4, 2, 3), glm::vec3(-1, 0, 0)}, HitQuery::Closest), 3.0f, 0, {1, 0, 0});
    // Past its tip at x = −1.
    EXPECT_FALSE(trace(tracer, Ray{glm::vec3(-1.01f, 5, 3), glm::vec3(0, -1, 0)}, HitQuery::Closest));
    expectHit(trace(tracer, Ray{glm::vec3(0, 10, 3), glm::vec3(0, 0, -1)}, HitQuery::Closest), 2.5f, 1, {0, 0, 1});
    // The surface spans x ∈ [20, 23], y ∈ [0, 3] at z = 0.
    expectHit(trace(tracer, Ray{glm::vec3(22.9f, 2.9f, 4), glm::vec3(0, 0, -2)}, HitQuery::Closest), 2.0f, 2,
              {0, 0, 1});
    EXPECT_FALSE(trace(tracer, Ray{glm::vec3(23.1f, 1, 4), glm::vec3(0, 0, -1)}, HitQuery::Closest));
    // The polygon faces +Z (counter-clockwise seen from above).
    expectHit(trace(tracer, Ray{glm::vec3(0.5f, 0.5f, -8), glm::vec3(0, 0, 1)}, HitQuery::Closest), 3.0f, 3, {0, 0, 1});
    EXPECT_EQ(trace(tracer, Ray{glm::vec3(0.5f, 0.5f, -8), glm::vec3(0, 0, 1)}, HitQuery::Closest)->material, 0u);
}

TEST(FlatTracer, ClosestHitIsTheNearestOfSeveral) {
    const PlantAsset plant = handMadePlant();
    const FlatTracer tracer = buildFlatTracer(plant);
    // Straight down x = 0, z = 0: misses the cylinder (at z = 3), hits the
    // sphere at y = 10.5, and the polygon's plane is never crossed.
    Ray down{glm::vec3(0, 20, 0), glm::vec3(0, -1, 0)};
    expectHit(trace(tracer, down, HitQuery::Closest), 9.5f, 1, {0, 1, 0});
    // Along −Z at x = 0.25, y = 2: through the cylinder (its far wall too) and then the polygon.
    Ray through{glm::vec3(0.25f, 2, 10), glm::vec3(0, 0, -1)};
    const std::optional<Hit> first = trace(tracer, through, HitQuery::Closest);
    ASSERT_TRUE(first.has_value());
    EXPECT_EQ(first->kind, PrimitiveKind::Segment);
    EXPECT_NEAR(first->t, 10.0f - 3.5f, 1e-5f);
    through.tMin = 10.0f - 2.0f; // past the cylinder
    expectHit(trace(tracer, through, HitQuery::Closest), 15.0f, 3, {0, 0, 1});
    // A shadow ray stopping short of everything.
    through.tMin = 0.0f;
    through.tMax = 6.0f;
    EXPECT_FALSE(trace(tracer, through, HitQuery::Any));
}

// The graph tracer carries the ray through each instance frame in single
// precision, while flattening composes the frames themselves: the two place
// a primitive a few single-precision ulps of the plant's size apart (within
// the flattening tests' tolerance), so a ray grazing a leaf's outline or a
// twig within that distance may hit in one and miss in the other. At most one ray in this many may differ; a wrong
// transform or a culled box makes far more differ.
constexpr size_t kRaysPerGrazingDifference = 1000;

// Closest hits of each PrimitiveKind.
using HitsByKind = std::array<size_t, 4>;

// Closest and any hits through the graph, walked with objects flattened up
// to `flattenedPrimitives`, and through its flattened plant.
HitsByKind compareTracers(const InstanceGraph& graph, size_t rayCount, uint64_t flattenedPrimitives) {
    const PlantAsset flat = flatten(graph);
    const FlatTracer flatTracer = buildFlatTracer(flat);
    const GraphTracer graphTracer = buildGraphTracer(graph, SurfaceLibrary{}, flattenedPrimitives);
    size_t hits = 0, differing = 0;
    HitsByKind byKind{};
    for (const Ray& ray : raysAt(flat.bounds, rayCount, 7)) {
        const std::optional<Hit> expected = trace(flatTracer, ray, HitQuery::Closest);
        const std::optional<Hit> actual = trace(graphTracer, ray, HitQuery::Closest);
        const bool same = expected.has_value() == actual.has_value() &&
                          (!expected || (std::abs(actual->t - expected->t) <= 1e-4f * expected->t &&
                                         actual->kind == expected->kind && actual->material == expected->material &&
                                         glm::dot(actual->normal, expected->normal) > 0.99f));
        if (!same && differing++ < 5)
            std::printf("differs: ray from (%g, %g, %g) along (%g, %g, %g): flat t %g, graph t %g\n", ray.origin.x,
                        ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                        expected ? expected->t : -1.0f, actual ? actual->t : -1.0f);
        hits += expected.has_value();
        if (expected) ++byKind[size_t(expected->kind)];
        // A shadow ray asks only whether anything is in the way.
        const std::optional<Hit> anyGraph = trace(graphTracer, ray, HitQuery::Any);
        const std::optional<Hit> anyFlat = trace(flatTracer, ray, HitQuery::Any);
        EXPECT_EQ(anyGraph.has_value(), actual.has_value());
        EXPECT_EQ(anyFlat.has_value(), expected.has_value());
        if (anyGraph && actual) {
            EXPECT_GE(anyGraph->t, actual->t);
        }
        // Nothing is nearer than the closest hit.
        if (actual) {
            Ray shorter = ray;
            shorter.tMax = actual->t * (1.0f - 1e-3f);
            EXPECT_FALSE(trace(graphTracer, shorter, HitQuery::Any));
        }
    }
    EXPECT_LE(differing, rayCount / kRaysPerGrazingDifference) << differing << " of " << rayCount << " rays differ";
    // The rays are aimed into the box: a good part of them must hit something.
    EXPECT_GT(hits, rayCount / 20);
    std::printf("%zu rays, %zu hit, %zu differ (objects of up to %llu primitives flattened)\n", rayCount, hits,
                differing, static_cast<unsigned long long>(flattenedPrimitives));
    return byKind;
}

// The same for each walk: objects flattened as by default (these plants
// whole), a few levels of small ones flattened under instances walked one by
// one, and every instance walked.
HitsByKind compareTracers(const InstanceGraph& graph, size_t rayCount) {
    for (uint64_t flattenedPrimitives : {uint64_t{64}, kNoFlattening})
        compareTracers(graph, rayCount, flattenedPrimitives);
    return compareTracers(graph, rayCount, kFlattenedPrimitives);
}

TEST(GraphTracer, FractalBushFourSteps) { compareTracers(graphOf(loadOk("plants/fractal_bush.lsys"), 4), 3000); }

TEST(GraphTracer, FractalBushFiveSteps) { compareTracers(graphOf(loadOk("plants/fractal_bush.lsys"), 5), 2000); }

TEST(GraphTracer, MonopodialTree) { compareTracers(graphOf(loadOk("plants/monopodial_tree.lsys")), 3000); }

// ~leaf surfaces on a sympodial crown.
TEST(GraphTracer, BroadleafWithLeafSurfaces) {
    const InstanceGraph graph = graphOf(loadOk("plants/broadleaf.lsys"));
    ASSERT_FALSE(graph.surfaceNames.empty());
    EXPECT_GT(compareTracers(graph, 3000)[size_t(PrimitiveKind::Surface)], 100u);
}

// `{ . }` polygons spanning branches (ABOP Fig 5.5).
TEST(GraphTracer, CordateLeafPolygons) {
    const InstanceGraph graph = graphOf(loadOk("plants/abop/fig5_5_cordate_leaf"));
    ASSERT_FALSE(graph.polygons.empty());
    EXPECT_GT(compareTracers(graph, 3000)[size_t(PrimitiveKind::Polygon)], 100u);
}

// A polygon in an object placed by rotated instances at every level.
TEST(GraphTracer, PolygonsInRotatedInstances) {
    const InstanceGraph graph = graphOf(parseOk("angle: 35\nAxiom: A\nA --> F[+&A]{.-f.+f.}F[-^A]\n"), 5);
    ASSERT_FALSE(graph.polygons.empty());
    ASSERT_FALSE(graph.instances.empty());
    EXPECT_GT(compareTracers(graph, 3000)[size_t(PrimitiveKind::Polygon)], 20u);
}

// A vlab object drawn with pixel-wide lines: the graph tracer makes them as
// wide as graph export does (a pixel is the root's box over
// kPixelsAcrossPlant), not as many world units as pixels.
TEST(GraphTracer, PixelWideLinesGetGraphExportsWidth) {
    const InstanceGraph graph = graphOf(loadOk("plants/abop/fig2_6a_monopodial_tree"));
    ASSERT_TRUE(graph.pixelLines);
    const GraphTracer tracer = buildGraphTracer(graph);
    const float pixel = worldPerPixel(graph.objects[graph.root].bounds);
    ASSERT_GT(pixel, 0.0f);
    ASSERT_LT(pixel, 0.1f);
    size_t segments = 0;
    for (size_t i = 0; i < graph.primitives.size(); ++i) {
        if (graph.primitives[i].kind != PrimitiveKind::Segment) continue;
        ++segments;
        EXPECT_FLOAT_EQ(tracer.primitives[i].startRadius, graph.primitives[i].startRadius * pixel);
        EXPECT_FLOAT_EQ(tracer.primitives[i].endRadius, graph.primitives[i].endRadius * pixel);
    }
    EXPECT_GT(segments, 0u);
}

// The walk enters the root and the children of every object it does not
// flatten; of those, objects drawing at most the budget are flattened. The
// 7-step bush's objects draw 8^k unit segments (k = 1 … 7): the 5-step one
// (32 768) is flattened whole, the 6- and 7-step ones are walked instance by
// instance, the smaller ones only inside the flattened one.
TEST(GraphTracer, FlattensTheLargestObjectsWithinTheBudget) {
    const InstanceGraph graph = graphOf(loadOk("plants/fractal_bush.lsys"), 7);
    const GraphTracer tracer = buildGraphTracer(graph);
    ASSERT_EQ(tracer.flattened.size(), 1u);
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        const uint64_t primitives = graph.objects[object].primitives;
        SCOPED_TRACE(primitives);
        EXPECT_EQ(tracer.flattenedIndex[object] != kNotFlattened, primitives == 32768u);
        EXPECT_EQ(tracer.objectWideBvhs[object].nodes.empty(), primitives <= 32768u);
        if (tracer.flattenedIndex[object] != kNotFlattened) {
            EXPECT_EQ(tracer.flattened[tracer.flattenedIndex[object]].leaves.size(), primitives);
        }
    }
    const GraphTracer unflattened = buildGraphTracer(graph, SurfaceLibrary{}, kNoFlattening);
    EXPECT_TRUE(unflattened.flattened.empty());
}

TEST(GraphTracer, LeafyPlantWithDecomposition) { compareTracers(graphOf(loadOk("plants/leafy_plant.lsys")), 3000); }

TEST(GraphTracer, SameRaysSameHits) {
    const InstanceGraph graph = graphOf(loadOk("plants/broadleaf.lsys"));
    const GraphTracer a = buildGraphTracer(graph), b = buildGraphTracer(graph);
    const PlantAsset flat = flatten(graph);
    for (const Ray& ray : raysAt(flat.bounds, 500, 11)) {
        for (HitQuery query : {HitQuery::Closest, HitQuery::Any}) {
            const std::optional<Hit> first = trace(a, ray, query), second = trace(b, ray, query);
            ASSERT_EQ(first.has_value(), second.has_value());
            if (!first) continue;
            EXPECT_EQ(first->t, second->t);
            EXPECT_EQ(first->primitive, second->primitive);
            EXPECT_EQ(first->normal, second->normal);
        }
    }
}

TEST(GraphTracer, AnEmptyGraphHitsNothing) {
    const InstanceGraph graph;
    const GraphTracer tracer = buildGraphTracer(graph);
    EXPECT_FALSE(trace(tracer, Ray{}, HitQuery::Closest));
}

} // namespace
} // namespace lsys::test
