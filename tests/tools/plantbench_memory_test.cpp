// plantbench's memory check with made-up limits: a count the device or the
// host cannot hold is refused with a message naming the count, the need and
// the limit (tools/plantbench/memory_check.h).
#include "memory_check.h"

#include "engine/raytrace/field_graph.h"

#include <gtest/gtest.h>

namespace pf {
namespace {

constexpr uint64_t kMiB = 1ull << 20, kGiB = 1ull << 30;
constexpr uint64_t kMaxPlants = 16777216;
constexpr Antialiasing kMsaa4{AntialiasMethod::msaa, 4};

void expectMentions(const std::string& message, std::initializer_list<std::string> parts) {
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
}

TEST(PlantbenchMemory, FieldEstimateGrowsWithThePlants) {
    const uint64_t fixed = estimatedFieldBytes(0, nullptr, 1280, 720, kMsaa4);
    EXPECT_GT(fixed, uint64_t(1280) * 720 * 4 * 4) << "the multisampled target at least";
    const uint64_t perPlant = estimatedFieldBytes(1000, nullptr, 1280, 720, kMsaa4) - fixed;
    EXPECT_EQ(perPlant % 1000, 0u);
    EXPECT_GE(perPlant / 1000, 48u + 3 * 4) << "an instance and a visible entry per LOD";
    PlantModelPool pool;
    pool.indices.resize(300);
    EXPECT_EQ(estimatedFieldBytes(1000, &pool, 1280, 720, kMsaa4) -
                  estimatedFieldBytes(1000, nullptr, 1280, 720, kMsaa4),
              300u * 4);
    EXPECT_EQ(estimatedHostBytes(1000, CountMode::Densify), 1000 * kHostBytesPerPlant);
    // At natural densities the grown terrain's heights come on top.
    EXPECT_EQ(estimatedHostBytes(1000, CountMode::NaturalDensity), 1000 * (kHostBytesPerPlant + 16 * 4));
}

// Ray-traced shadows add the field's graph (a model's triangles once, every
// plant's instance) and three frame-sized images.
TEST(PlantbenchMemory, FieldEstimateCountsTheTracedShadowsGraphAndImages) {
    const uint64_t pixels = uint64_t(1280) * 720;
    PlantModelPool pool;
    pool.models.resize(1);
    pool.indices.resize(3000);
    pool.models[0].meshes[LOD_FULL][DRAW_BARK] = {0, 3000, 0};
    const uint64_t map = estimatedFieldBytes(1000, &pool, 1280, 720, kMsaa4);
    const uint64_t traced = estimatedFieldBytes(1000, &pool, 1280, 720, kMsaa4, SunShadows::raytraced);
    EXPECT_EQ(traced - map, fieldGraphBytes(pool, 1000) + pixels * 24);
    EXPECT_GT(fieldGraphBytes(pool, 1000), fieldGraphBytes(PlantModelPool{}, 1000)) << "the model's triangles";
    EXPECT_GT(fieldGraphBytes(PlantModelPool{}, 1000), 1000u * sizeof(gpu::RtInstance)) << "the plants' instances";
    EXPECT_EQ(estimatedFieldBytes(1000, &pool, 1280, 720, kMsaa4, SunShadows::none), map);
}

// FXAA's one-sample image the colour pass draws into, besides the finished one.
TEST(PlantbenchMemory, FieldEstimateCountsTheFxaaImage) {
    const uint64_t pixels = uint64_t(1280) * 720;
    EXPECT_EQ(estimatedFieldBytes(0, nullptr, 1280, 720, {AntialiasMethod::fxaa}) -
                  estimatedFieldBytes(0, nullptr, 1280, 720, {AntialiasMethod::none}),
              pixels * 4);
    EXPECT_LT(estimatedFieldBytes(0, nullptr, 1280, 720, {AntialiasMethod::fxaa}),
              estimatedFieldBytes(0, nullptr, 1280, 720, kMsaa4));
}

TEST(PlantbenchMemory, FittingCountIsAccepted) {
    EXPECT_EQ(gpuMemoryProblem(100000, estimatedFieldBytes(100000, nullptr, 1280, 720, kMsaa4), "fake GPU",
                               {4 * kGiB, false}),
              "");
    EXPECT_EQ(hostMemoryProblem(100000, estimatedHostBytes(100000, CountMode::NaturalDensity), {8 * kGiB}), "");
}

TEST(PlantbenchMemory, CountAboveTheHeapIsRefusedNamingCountNeedAndHeap) {
    const uint64_t need = estimatedFieldBytes(kMaxPlants, nullptr, 1280, 720, kMsaa4);
    ASSERT_GT(need, 512 * kMiB);
    expectMentions(gpuMemoryProblem(kMaxPlants, need, "fake GPU", {512 * kMiB, false}),
                   {"16777216 plants", lsys::formatBytes(need), "GPU memory", "fake GPU", "holds 512.0 MiB",
                    "measure fewer plants"});
}

TEST(PlantbenchMemory, HeapBudgetIsNamedAsABudget) {
    expectMentions(gpuMemoryProblem(1000, 300 * kMiB, "fake GPU", {256 * kMiB, true}),
                   {"1000 plants", "300.0 MiB", "budget of 256.0 MiB"});
}

TEST(PlantbenchMemory, CountAboveTheMemoryBudgetIsRefused) {
    const uint64_t need = estimatedHostBytes(kMaxPlants, CountMode::NaturalDensity);
    ASSERT_GT(need, 100 * kMiB);
    expectMentions(hostMemoryProblem(kMaxPlants, need, {100 * kMiB}),
                   {"16777216 plants", lsys::formatBytes(need), "host memory", "memory budget is 100.0 MiB",
                    "--memory-budget", "measure fewer plants"});
}

} // namespace
} // namespace pf
