// The growth law of the Calgary b-grammar thesis: for a D0L bush the hierarchy
// grows linearly with the number of steps while the primitives it stands for
// grow geometrically; the 9-step bush (134 M segments) is built without
// expanding anything.

#include <chrono>
#include <cstdio>

#include "instance_graph_test_support.h"

namespace lsys::test {
namespace {

struct Timed {
    InstanceGraphStats stats;
    double seconds = 0.0;
};

Timed bushStats(const Grammar& grammar, int steps, const InstanceGraphOptions& options = {}) {
    const auto start = std::chrono::steady_clock::now();
    const InstanceGraph graph = graphOf(grammar, steps, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {instanceGraphStats(graph), seconds};
}

TEST(InstanceGraphGrowth, ObjectsGrowLinearlyWhilePrimitivesGrowGeometrically) {
    const Grammar grammar = loadOk("plants/fractal_bush.lsys");
    std::vector<InstanceGraphStats> stats;
    for (int steps = 1; steps <= 10; ++steps) {
        const Timed timed = bushStats(grammar, steps);
        stats.push_back(timed.stats);
        std::printf("bush %2d steps: nodes %3zu objects %3zu instances %4llu primitives %12llu compression %12.1f "
                    "bytes %7zu / %14zu  %.5fs\n",
                    steps, timed.stats.nodes, timed.stats.objects,
                    static_cast<unsigned long long>(timed.stats.instances),
                    static_cast<unsigned long long>(timed.stats.primitives), timed.stats.compression(),
                    timed.stats.bytesGraph, timed.stats.bytesFlat, timed.seconds);
    }
    for (size_t i = 2; i + 1 < stats.size(); ++i) {
        SCOPED_TRACE(i + 1);
        EXPECT_EQ(stats[i + 1].objects - stats[i].objects, stats[i].objects - stats[i - 1].objects);
        EXPECT_EQ(stats[i + 1].instances - stats[i].instances, stats[i].instances - stats[i - 1].instances);
        EXPECT_EQ(stats[i + 1].primitives, 8 * stats[i].primitives);
        EXPECT_EQ(stats[i].objects, stats[i].nodes); // nothing but the node tells objects apart
    }
}

TEST(InstanceGraphGrowth, NineStepBushIsBuiltWithoutExpanding) {
    const Grammar grammar = loadOk("plants/fractal_bush.lsys");
    const Timed nine = bushStats(grammar, 9);
    EXPECT_EQ(nine.stats.primitives, 134'217'728u); // 8^9 segments
    EXPECT_EQ(nine.stats.joints, nine.stats.primitives);
    EXPECT_LT(nine.stats.instances, 200u);
    EXPECT_LT(nine.stats.bytesGraph, 64u * 1024u);
    std::printf("bush 9 steps: %llu primitives in %llu instances (%.0f:1), %zu bytes vs %zu flat, built in %.5fs\n",
                static_cast<unsigned long long>(nine.stats.primitives),
                static_cast<unsigned long long>(nine.stats.instances), nine.stats.compression(), nine.stats.bytesGraph,
                nine.stats.bytesFlat, nine.seconds);
    // Past 2^31 joints the references stay 64-bit.
    const Timed twelve = bushStats(grammar, 12);
    EXPECT_EQ(twelve.stats.joints, 68'719'476'736u);
}

TEST(InstanceGraphGrowth, FlattenRefusesPastItsBudget) {
    const Grammar grammar = loadOk("plants/fractal_bush.lsys");
    EXPECT_THROW(flatten(graphOf(grammar, 9), SurfaceLibrary{}, 1'000'000), DerivationError);
}

} // namespace
} // namespace lsys::test
