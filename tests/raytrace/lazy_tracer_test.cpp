// The lazy graph tracer (Robbins 1998, §3): objects interpreted again from
// the b-grammar on demand, held in an LRU cache, give the hits of
// GraphTracer's walk through every instance bit for bit, whatever the
// cache's budget, from one thread or several.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "../instance_graph/instance_graph_test_support.h"
#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/raytrace/lazy_graph_tracer.h"
#include "seeded_rays.h"

namespace lsys::test {
namespace {

// A plant's graph both ways: built whole, and derived for lazy expansion.
struct BothGraphs {
    InstanceGraph whole;
    LazyInstanceGraph lazy;
};

BothGraphs bothGraphs(const Grammar& grammar, std::optional<int> steps = std::nullopt) {
    const BGrammar bgrammar = interpretedBGrammar(grammar, steps);
    return {buildInstanceGraph(bgrammar, grammar), deriveLazyInstanceGraph(bgrammar, grammar)};
}

// Which primitives overlap exactly: none, or copies of one shape placed at
// the same spot along different paths of instances (the fractal bush's
// F → FF stacks unit segments that way), where which copy a walk meets
// first is the order of the walk, and the copies' normals differ in their
// last bits (each rotated back along its own path).
enum class Overlaps { None, CoincidentCopies };

void expectSameHit(const std::optional<Hit>& actual, const std::optional<Hit>& expected, Overlaps overlaps) {
    ASSERT_EQ(actual.has_value(), expected.has_value());
    if (!expected) return;
    EXPECT_EQ(actual->t, expected->t);
    EXPECT_EQ(actual->kind, expected->kind);
    EXPECT_EQ(actual->material, expected->material);
    if (overlaps == Overlaps::CoincidentCopies) {
        EXPECT_LT(glm::distance(actual->normal, expected->normal), 1e-4f); // float rotations, 5 levels
        return;
    }
    EXPECT_EQ(actual->primitive, expected->primitive);
    EXPECT_EQ(actual->normal, expected->normal);
}

// Closest and any hits of seeded rays through both tracers, the lazy one
// under `budgetBytes`.
void expectGraphTracersHits(const BothGraphs& graphs, uint64_t budgetBytes, size_t rayCount, Overlaps overlaps) {
    // GraphTracer's walk through every instance, the walk the lazy tracer
    // makes (flattened objects' composed frames round otherwise).
    const GraphTracer whole = buildGraphTracer(graphs.whole, SurfaceLibrary{}, kNoFlattening);
    const LazyGraphTracer lazy = buildLazyGraphTracer(graphs.lazy, budgetBytes);
    size_t hits = 0;
    for (const Ray& ray : raysAt(graphs.whole.objects[graphs.whole.root].bounds, rayCount, 5)) {
        const std::optional<Hit> expected = trace(whole, ray, HitQuery::Closest);
        expectSameHit(trace(lazy, ray, HitQuery::Closest), expected, overlaps);
        hits += expected.has_value();
        // Any hit is whichever the walk meets first, and the graph tracer
        // boxes instances from their descendants where the lazy one has only
        // the child's box, so their walks differ: both must agree that
        // something is in the way, and the lazy one's hit be no nearer than
        // the closest.
        const std::optional<Hit> any = trace(lazy, ray, HitQuery::Any);
        ASSERT_EQ(any.has_value(), expected.has_value());
        if (any) {
            EXPECT_GE(any->t, expected->t);
        }
    }
    // Aimed into the box, some hit (a few percent of them on pixel-wide lines).
    EXPECT_GT(hits, rayCount / 40);
    EXPECT_LE(expansionStats(lazy).peakBytes, budgetBytes);
}

void expectLazyIsWhole(const Grammar& grammar, std::optional<int> steps = std::nullopt,
                       Overlaps overlaps = Overlaps::None) {
    const BothGraphs graphs = bothGraphs(grammar, steps);
    for (uint64_t budget : {uint64_t{1}, uint64_t{16} << 10, UINT64_MAX})
        expectGraphTracersHits(graphs, budget, 500, overlaps);
}

TEST(LazyGraphTracer, FractalBushFiveStepsIsTheGraphTracer) {
    expectLazyIsWhole(loadOk("plants/fractal_bush.lsys"), 5, Overlaps::CoincidentCopies);
}

TEST(LazyGraphTracer, MonopodialTreeIsTheGraphTracer) { expectLazyIsWhole(loadOk("plants/monopodial_tree.lsys")); }

TEST(LazyGraphTracer, LeafSurfacesAreTheGraphTracers) { expectLazyIsWhole(loadOk("plants/broadleaf.lsys")); }

TEST(LazyGraphTracer, PolygonsAreTheGraphTracers) { expectLazyIsWhole(loadOk("plants/abop/fig5_5_cordate_leaf")); }

TEST(LazyGraphTracer, PixelWideLinesAreTheGraphTracers) {
    expectLazyIsWhole(loadOk("plants/abop/fig2_6a_monopodial_tree"));
}

TEST(LazyGraphTracer, LeafyPlantWithDecompositionIsTheGraphTracer) {
    expectLazyIsWhole(loadOk("plants/leafy_plant.lsys"));
}

// A pinhole camera's closest hits, row by row: t and primitive per pixel.
struct Pixel {
    float t = -1.0f;
    uint32_t primitive = UINT32_MAX;
    friend bool operator==(const Pixel&, const Pixel&) = default;
};

std::vector<Pixel> image(const LazyGraphTracer& tracer, const Bounds& bounds, int size) {
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    const float extent = glm::length(bounds.max - bounds.min);
    const glm::vec3 eye = centre + glm::vec3(0.3f, 0.2f, 1.5f) * extent;
    const glm::vec3 forward = glm::normalize(centre - eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    std::vector<Pixel> pixels;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float u = (x + 0.5f) / size - 0.5f, v = 0.5f - (y + 0.5f) / size;
            const std::optional<Hit> hit =
                trace(tracer, Ray{eye, glm::normalize(forward + 0.8f * (u * right + v * up))}, HitQuery::Closest);
            pixels.push_back(hit ? Pixel{hit->t, hit->primitive} : Pixel{});
        }
    return pixels;
}

TEST(LazyGraphTracer, TinyAndUnlimitedCachesGiveTheSameImage) {
    const BothGraphs graphs = bothGraphs(loadOk("plants/fractal_bush.lsys"), 5);
    const Bounds& bounds = graphs.whole.objects[graphs.whole.root].bounds;
    const size_t objects = graphs.lazy.graph.objects.size();

    const LazyGraphTracer unlimited = buildLazyGraphTracer(graphs.lazy, UINT64_MAX);
    const std::vector<Pixel> expected = image(unlimited, bounds, 64);
    EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](const Pixel& p) { return p.t > 0.0f; }), 200);
    EXPECT_EQ(expansionStats(unlimited).expansions, objects); // each once
    EXPECT_EQ(expansionStats(unlimited).evictions, 0u);

    // One byte holds nothing: every object entered is expanded, used and dropped.
    const LazyGraphTracer none = buildLazyGraphTracer(graphs.lazy, 1);
    EXPECT_EQ(image(none, bounds, 64), expected);
    EXPECT_GT(expansionStats(none).expansions, 100 * objects);
    EXPECT_EQ(expansionStats(none).peakBytes, 0u);

    // Room for half of them: objects keep displacing each other.
    const uint64_t half = expansionStats(unlimited).bytesHeld / 2;
    const LazyGraphTracer some = buildLazyGraphTracer(graphs.lazy, half);
    EXPECT_EQ(image(some, bounds, 64), expected);
    EXPECT_GT(expansionStats(some).evictions, 0u);
    EXPECT_LE(expansionStats(some).peakBytes, half);
    EXPECT_LE(expansionStats(some).bytesHeld, half);
}

// Threads tracing one tracer share its cache: the same pixels as one thread.
TEST(LazyGraphTracer, ThreadsSharingACacheGiveTheSameImage) {
    const BothGraphs graphs = bothGraphs(loadOk("plants/fractal_bush.lsys"), 5);
    const Bounds& bounds = graphs.whole.objects[graphs.whole.root].bounds;
    const LazyGraphTracer alone = buildLazyGraphTracer(graphs.lazy, UINT64_MAX);
    const std::vector<Pixel> expected = image(alone, bounds, 64);
    const LazyGraphTracer shared = buildLazyGraphTracer(graphs.lazy, expansionStats(alone).bytesHeld / 3);
    std::vector<std::vector<Pixel>> images(4);
    std::vector<std::thread> threads;
    for (std::vector<Pixel>& pixels : images) threads.emplace_back([&] { pixels = image(shared, bounds, 64); });
    for (std::thread& thread : threads) thread.join();
    for (const std::vector<Pixel>& pixels : images) EXPECT_EQ(pixels, expected);
    EXPECT_GT(expansionStats(shared).evictions, 0u);
}

} // namespace
} // namespace lsys::test
