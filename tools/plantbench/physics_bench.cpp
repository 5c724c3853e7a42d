// physics_bench: the GPU physics + pose passes (engine/physics/physics_pass.h)
// against the CPU reference on one thread (engine/physics/plant_physics.h), one
// frame of 8 sub-steps and the pose per iteration, for 10 000, 100 000 and
// 1 000 000 joints: skeletons of the default scene's plant models, cloned
// one model after another over a 1 km square in the scene's wind.
//
// GPU time is the timestamp queries around the recorded passes
// (engine/vk/gpu_timer.h, the benchmark's manual time), with physics_ms and
// pose_ms the passes' own scopes (recordPhysicsPass); wall_ms adds the
// submit and the wait. The counter joint_steps_per_ms is joints × sub-steps per
// millisecond of that time (GPU: timestamps; CPU: wall time of one thread).
#include "tools/field_options.h"

#include "engine/physics/physics_pass.h"
#include "engine/scene/plant_models.h"
#include "engine/vk/gpu_timer.h"

#include <benchmark/benchmark.h>
#include <plantfield_version.h>

#include <chrono>
#include <cstdio>
#include <string_view>

namespace pf {
namespace {

constexpr uint32_t kStepsPerFrame = 8;

struct Models {
    Scene scene;
    PlantModelPool pool;
};

const Models& defaultModels() {
    static const Models models = [] {
        Models m;
        m.scene = loadScene(defaultScenePath());
        m.pool = buildPlantModels(m.scene);
        return m;
    }();
    return models;
}

// Whole skeletons of the models in turn, skipping those that would exceed
// `joints`, until none fits: a few joints short of it at most.
SkeletonSet cloneForest(const PlantModelPool& pool, uint32_t joints) {
    SkeletonSet set;
    set.params = pool.joints;
    const uint32_t models = uint32_t(pool.models.size());
    for (uint32_t i = 0, misses = 0; misses < models; ++i) {
        const PlantModelInfo& model = pool.models[i % models];
        if (set.states.size() + model.joints > joints) {
            ++misses;
            continue;
        }
        misses = 0;
        const uint32_t n = uint32_t(set.skeletons.size());
        const glm::vec3 position(float(n % 1000), 0.0f, float(n / 1000 % 1000));
        addSkeleton(set, i % models, model.firstJoint, model.joints, position, 0.37f * float(n), 1.0f);
    }
    return set;
}

gpu::PhysicsUniforms frameUniforms(const Scene& scene, const SkeletonSet& set, uint64_t frame) {
    const float dt = scene.physics.subStep;
    return makePhysicsUniforms(scene.wind, scene.physics, float(double(frame) * kStepsPerFrame * dt), dt,
                               kStepsPerFrame, uint32_t(set.skeletons.size()), uint32_t(set.states.size()));
}

void setCounters(benchmark::State& state, size_t joints, double totalMs) {
    state.counters["joints"] = double(joints);
    state.counters["joint_steps_per_ms"] = double(joints) * kStepsPerFrame * double(state.iterations()) / totalMs;
}

GpuContext& benchContext() {
    static GpuContext ctx = [] {
        GpuContext c;
        createHeadlessContext(c, GpuOptions{});
        return c;
    }();
    return ctx;
}

void BM_GpuPhysicsPose(benchmark::State& state) {
    const Models& models = defaultModels();
    const GpuContext& ctx = benchContext();
    const SkeletonSet set = cloneForest(models.pool, uint32_t(state.range(0)));
    GpuResources resources(ctx);
    PhysicsPass pass = createPhysicsPass(resources, set);
    GpuTimer timer = createGpuTimer(ctx, 3); // physics+pose, and inside it physics and pose
    if (!timer.supported) state.SkipWithError("the queue writes no timestamps");
    uint64_t frame = 0;
    double totalMs = 0.0, wallMs = 0.0, physicsMs = 0.0, poseMs = 0.0;
    for (auto _ : state) {
        setPhysicsUniforms(pass, frameUniforms(models.scene, set, frame++));
        const auto start = std::chrono::steady_clock::now();
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            resetGpuTimer(cmd, timer);
            beginScopeOutsideRendering(cmd, timer, "physics+pose");
            recordPhysicsPass(cmd, pass, &timer);
            endScope(cmd, timer);
        });
        wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const std::vector<ScopeTime> scopes = readGpuTimer(ctx, timer);
        const double ms = scopes.at(0).milliseconds;
        physicsMs += scopes.at(1).milliseconds;
        poseMs += scopes.at(2).milliseconds;
        state.SetIterationTime(ms / 1000.0);
        totalMs += ms;
    }
    setCounters(state, set.states.size(), totalMs);
    state.counters["wall_ms"] = benchmark::Counter(wallMs, benchmark::Counter::kAvgIterations);
    state.counters["physics_ms"] = benchmark::Counter(physicsMs, benchmark::Counter::kAvgIterations);
    state.counters["pose_ms"] = benchmark::Counter(poseMs, benchmark::Counter::kAvgIterations);
    destroyGpuTimer(ctx, timer);
}

void BM_CpuReference(benchmark::State& state) {
    const Models& models = defaultModels();
    SkeletonSet set = cloneForest(models.pool, uint32_t(state.range(0)));
    uint64_t frame = 0;
    double totalMs = 0.0;
    for (auto _ : state) {
        const gpu::PhysicsUniforms u = frameUniforms(models.scene, set, frame++);
        const auto start = std::chrono::steady_clock::now();
        stepSkeletonsOnCpu(set, u);
        poseSkeletonsOnCpu(set);
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    setCounters(state, set.states.size(), totalMs);
}

BENCHMARK(BM_GpuPhysicsPose)->Arg(10000)->Arg(100000)->Arg(1000000)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuReference)->Arg(10000)->Arg(100000)->Arg(1000000)->UseRealTime()->Unit(benchmark::kMillisecond);

} // namespace
} // namespace pf

int main(int argc, char** argv) {
    // Google Benchmark's flags have no --version; every tool of the project answers it alike.
    for (int i = 1; i < argc; ++i)
        if (std::string_view(argv[i]) == "--version") {
            std::printf("physics_bench %s\n", pf::kPlantfieldVersion);
            return 0;
        }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    pf::destroyContext(pf::benchContext());
    return 0;
}
