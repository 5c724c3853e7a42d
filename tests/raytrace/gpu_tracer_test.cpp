// The GPU traversal (shaders/raytrace_traverse.glsl through
// engine/raytrace/raytrace_pass.h) against lsys::trace(GraphTracer) on
// plant files: the same hit or miss, primitive and t for the same rays, on
// lavapipe with the validation layer on.

#include "gpu_test.h"

#include "../instance_graph/instance_graph_test_support.h"
#include "chain_graph.h"
#include "engine/raytrace/raytrace_pass.h"
#include "seeded_rays.h"

#include <array>
#include <cstdio>
#include <optional>

namespace pf::test {
namespace {

using lsys::GraphTracer;
using lsys::Hit;
using lsys::HitQuery;
using lsys::InstanceGraph;
using lsys::Ray;

// t of the same hit agrees within this, relative (as the CPU tracers' tests
// ask of each other): the GPU solves in single precision what the CPU solves
// in double, after carrying the ray through the same single-precision
// frames. Measured: within 1.4e-5 on lavapipe.
constexpr float kRelativeT = 1e-4f;

// A ray is grazing when the CPU itself answers differently for the ray moved
// across itself by this much of the plant's size: it passes that close to an
// edge or a silhouette (or meets a face so obliquely that its t moves by
// more than kRelativeT), closer than single-precision frames place
// primitives. Only such rays may be answered differently by the GPU.
constexpr float kGrazingNudge = 1e-5f;

// And at most one ray in this many: a wrong frame or a culled box makes far
// more differ.
constexpr size_t kRaysPerGrazingDifference = 1000;

gpu::RtRay gpuRay(const Ray& ray) { return {ray.origin, ray.tMin, ray.direction, ray.tMax}; }

std::optional<Hit> asHit(const gpu::RtHit& hit) {
    if (hit.primitive == RAYTRACE_NO_HIT) return std::nullopt;
    return Hit{hit.t, lsys::PrimitiveKind(hit.kind), hit.material, hit.primitive, hit.normal};
}

// The same hit or miss: t within kRelativeT, the same normal, and the same
// primitive or one that coincides with it there. The fractal bush places
// copies of a unit segment at the same place along different paths of
// instances; the frames put them a few ulps apart, so which copy is nearer
// is rounding, in either tracer. A copy is the same kind and material.
bool sameAnswer(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return std::abs(a->t - b->t) <= kRelativeT * std::abs(b->t) && glm::dot(a->normal, b->normal) > 0.99f &&
           (a->primitive == b->primitive || (a->kind == b->kind && a->material == b->material));
}

bool cpuCallsGrazing(const GraphTracer& tracer, const Ray& ray, float nudge) {
    const std::optional<Hit> answer = trace(tracer, ray, HitQuery::Closest);
    const glm::vec3 across = glm::normalize(glm::cross(ray.direction, glm::vec3(0.36f, 0.48f, 0.8f)));
    const glm::vec3 other = glm::normalize(glm::cross(ray.direction, across));
    for (const glm::vec3& offset : {across, -across, other, -other}) {
        Ray moved = ray;
        moved.origin += nudge * offset;
        if (!sameAnswer(trace(tracer, moved, HitQuery::Closest), answer)) return true;
    }
    return false;
}

struct Comparison {
    size_t hits = 0;                // closest hits on the CPU
    size_t differing = 0;           // rays the GPU answers differently (all grazing)
    size_t coincident = 0;          // the same hit on another copy of the CPU's primitive
    float largestRelativeT = 0.0f;  // between the same hits
    uint32_t stackUsed = 0;         // the most stack entries a ray's walk held
    std::array<size_t, 4> byKind{}; // closest hits of each PrimitiveKind
};

class GpuTracerTest : public GpuTest {
protected:
    // Closest and any hits on the GPU against the CPU's for seeded rays.
    Comparison compare(const InstanceGraph& graph, size_t rayCount) {
        const GraphTracer tracer = lsys::buildGraphTracer(graph);
        const GpuGraph packed = packGraph(tracer);
        const RaytracePass pass = createRaytracePass(resources, uploadGraph(resources, packed), uint32_t(rayCount));
        // The flattened plant's box: the root object's, the box of its
        // children's boxes turned by their frames, grows with every level.
        const lsys::Bounds bounds = lsys::flatten(graph).bounds;
        const float nudge = kGrazingNudge * glm::length(bounds.max - bounds.min);
        const std::vector<Ray> rays = lsys::test::raysAt(bounds, rayCount, 7);
        std::vector<gpu::RtRay> gpuRays;
        for (const Ray& ray : rays) gpuRays.push_back(gpuRay(ray));
        const std::vector<gpu::RtHit> closest = traceRays(ctx, pass, gpuRays, HitQuery::Closest);
        const std::vector<gpu::RtHit> any = traceRays(ctx, pass, gpuRays, HitQuery::Any);

        Comparison result;
        // packGraph's bound on the stack holds for every walk.
        for (const std::vector<gpu::RtHit>* hits : {&closest, &any})
            for (const gpu::RtHit& hit : *hits) result.stackUsed = std::max(result.stackUsed, hit.stackUsed);
        EXPECT_LE(result.stackUsed, packed.stackDepth);
        std::vector<gpu::RtRay> shortened;
        for (size_t i = 0; i < rays.size(); ++i) {
            const std::optional<Hit> expected = trace(tracer, rays[i], HitQuery::Closest);
            const std::optional<Hit> actual = asHit(closest[i]);
            result.hits += expected.has_value();
            if (expected) ++result.byKind[size_t(expected->kind)];
            if (!sameAnswer(actual, expected)) {
                const bool grazing = cpuCallsGrazing(tracer, rays[i], nudge);
                EXPECT_TRUE(grazing) << "ray " << i << " from (" << rays[i].origin.x << ", " << rays[i].origin.y << ", "
                                     << rays[i].origin.z << "): CPU t " << (expected ? expected->t : -1.0f)
                                     << " primitive " << (expected ? int64_t(expected->primitive) : -1) << ", GPU t "
                                     << (actual ? actual->t : -1.0f) << " primitive "
                                     << (actual ? int64_t(actual->primitive) : -1);
                ++result.differing;
            } else if (actual) {
                const lsys::GraphPrimitive& primitive = graph.primitives[actual->primitive];
                EXPECT_EQ(actual->kind, primitive.kind) << "ray " << i;
                EXPECT_EQ(actual->material, primitive.material) << "ray " << i;
                result.coincident += actual->primitive != expected->primitive;
                result.largestRelativeT =
                    std::max(result.largestRelativeT, std::abs(actual->t - expected->t) / expected->t);
            }
            // A shadow ray asks only whether anything is in the way.
            EXPECT_EQ(any[i].primitive == RAYTRACE_NO_HIT, closest[i].primitive == RAYTRACE_NO_HIT) << "ray " << i;
            if (actual) {
                EXPECT_GE(any[i].t, actual->t) << "ray " << i;
                gpu::RtRay shorter = gpuRays[i];
                shorter.tMax = actual->t * (1.0f - 1e-3f);
                shortened.push_back(shorter);
            }
        }
        // Nothing is nearer than the closest hit.
        const std::vector<gpu::RtHit> nearer = traceRays(ctx, pass, shortened, HitQuery::Any);
        for (const gpu::RtHit& hit : nearer) EXPECT_EQ(hit.primitive, RAYTRACE_NO_HIT);

        EXPECT_LE(result.differing, rayCount / kRaysPerGrazingDifference)
            << result.differing << " of " << rayCount << " rays differ";
        // The rays are aimed into the box: a good part of them must hit something.
        EXPECT_GT(result.hits, rayCount / 20);
        std::printf("%zu rays, %zu hit, %zu differ (grazing), %zu on a coincident copy, t within %.2g; %u levels, "
                    "stack %u of at most %u\n",
                    rayCount, result.hits, result.differing, result.coincident, result.largestRelativeT, packed.levels,
                    result.stackUsed, packed.stackDepth);
        return result;
    }
};

TEST_F(GpuTracerTest, FractalBushFiveStepsMatchesTheCpu) {
    const Comparison c = compare(lsys::test::graphOf(lsys::test::loadOk("plants/fractal_bush.lsys"), 5), 4000);
    EXPECT_GT(c.byKind[size_t(lsys::PrimitiveKind::Segment)], 400u);
}

// ~leaf surfaces on a sympodial crown.
TEST_F(GpuTracerTest, BroadleafSurfacesMatchTheCpu) {
    const Comparison c = compare(lsys::test::graphOf(lsys::test::loadOk("plants/broadleaf.lsys")), 3000);
    EXPECT_GT(c.byKind[size_t(lsys::PrimitiveKind::Surface)], 100u);
}

// Spheres and `{ . }` polygons in objects placed by rotated instances at every level.
TEST_F(GpuTracerTest, SpheresAndPolygonsInRotatedInstancesMatchTheCpu) {
    const InstanceGraph graph =
        lsys::test::graphOf(lsys::test::parseOk("angle: 35\nAxiom: A\nA --> F[+&A]{.-f.+f.}F[-^A]@O(1.2)\n"), 5);
    ASSERT_FALSE(graph.instances.empty());
    const Comparison c = compare(graph, 3000);
    EXPECT_GT(c.byKind[size_t(lsys::PrimitiveKind::Sphere)], 50u);
    EXPECT_GT(c.byKind[size_t(lsys::PrimitiveKind::Polygon)], 20u);
}

// ABOP Fig 5.5's cordate leaf: polygons spanning branches.
TEST_F(GpuTracerTest, CordateLeafPolygonsMatchTheCpu) {
    const Comparison c = compare(lsys::test::graphOf(lsys::test::loadOk("plants/abop/fig5_5_cordate_leaf")), 3000);
    EXPECT_GT(c.byKind[size_t(lsys::PrimitiveKind::Polygon)], 100u);
}

// As many instance levels as the traversal holds, and a stack nearly as deep.
TEST_F(GpuTracerTest, TheDeepestGraphTheTraversalHoldsMatchesTheCpu) {
    const InstanceGraph graph = chainGraph(RAYTRACE_MAX_LEVELS, 15);
    const GpuGraph packed = packGraph(lsys::buildGraphTracer(graph));
    ASSERT_EQ(packed.levels, uint32_t(RAYTRACE_MAX_LEVELS));
    EXPECT_GT(packed.stackDepth, uint32_t(RAYTRACE_STACK_SIZE) * 3 / 4);
    compare(graph, 3000);
}

TEST_F(GpuTracerTest, AnEmptyGraphHitsNothing) {
    const InstanceGraph graph;
    const GpuGraph packed = packGraph(lsys::buildGraphTracer(graph));
    EXPECT_EQ(packed.rootNode, RAYTRACE_NO_NODE);
    const RaytracePass pass = createRaytracePass(resources, uploadGraph(resources, packed), 1);
    const gpu::RtRay ray = gpuRay(Ray{});
    EXPECT_EQ(traceRays(ctx, pass, {&ray, 1}, HitQuery::Closest)[0].primitive, RAYTRACE_NO_HIT);
}

} // namespace
} // namespace pf::test
