// plantfield --physics-check: one skeleton of every plant model of the scene,
// at the origin, simulated for 600 sub-steps of the scene's physics in the
// scene's wind on the GPU (engine/physics/physics_pass.h, frames of 8 sub-steps) and on
// the CPU reference (engine/physics/plant_physics.h); prints the largest rotation
// difference of any joint's state or pose as JSON.
#include "field_setup.h"
#include "modes.h"

#include "engine/physics/physics_pass.h"
#include "engine/scene/plant_models.h"
#include "engine/vk/gpu_timer.h"
#include "shaders/shared/joint_physics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

namespace pf {
namespace {

constexpr uint32_t kSteps = 600;
constexpr uint32_t kStepsPerFrame = 8;
constexpr double kMaxDeviationRad = 1e-3;

// The angle of the rotation taking b to a.
float angleBetween(const glm::vec4& a, const glm::vec4& b) {
    return glm::length(gpu::rotationVectorOf(gpu::quatMultiply(a, gpu::quatConjugate(b))));
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int runPhysicsCheck(const PlantfieldOptions& o) {
    const Scene scene = loadSceneOf(o);
    const PlantModelPool pool = buildPlantModels(scene);

    SkeletonSet cpu;
    cpu.params = pool.joints;
    for (uint32_t m = 0; m < pool.models.size(); ++m)
        addSkeleton(cpu, m, pool.models[m].firstJoint, pool.models[m].joints, glm::vec3(0.0f), 0.0f, 1.0f);
    const uint32_t joints = uint32_t(cpu.states.size()), skeletons = uint32_t(cpu.skeletons.size());
    const float dt = scene.physics.subStep;

    GpuContext ctx;
    createHeadlessContext(ctx, gpuOptions(o));
    GpuResources resources(ctx);
    PhysicsPass pass = createPhysicsPass(resources, cpu);
    GpuTimer timer = createGpuTimer(ctx, 1);

    // GPU time: the timestamps around each frame's passes, summed; wall
    // time of each submit and wait where the queue writes no timestamps.
    double gpuMs = 0.0, cpuMs = 0.0;
    for (uint32_t step = 0; step < kSteps; step += kStepsPerFrame) {
        const gpu::PhysicsUniforms u = makePhysicsUniforms(scene.wind, scene.physics, float(o.time + step * double(dt)),
                                                           dt, kStepsPerFrame, skeletons, joints);
        setPhysicsUniforms(pass, u);
        const auto gpuStart = std::chrono::steady_clock::now();
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            resetGpuTimer(cmd, timer);
            beginScopeOutsideRendering(cmd, timer, kPhysicsScope);
            recordPhysicsPass(cmd, pass);
            endScope(cmd, timer);
        });
        const double wallMs = millisecondsSince(gpuStart);
        const std::vector<ScopeTime> times = readGpuTimer(ctx, timer);
        gpuMs += timer.supported && !times.empty() ? times.front().milliseconds : wallMs;

        const auto cpuStart = std::chrono::steady_clock::now();
        stepSkeletonsOnCpu(cpu, u);
        poseSkeletonsOnCpu(cpu);
        cpuMs += millisecondsSince(cpuStart);
    }

    std::vector<gpu::JointState> states;
    std::vector<gpu::JointPose> poses;
    readPhysicsState(ctx, pass, states, poses);
    destroyGpuTimer(ctx, timer);
    resources.destroy();
    destroyContext(ctx);

    double deviation = 0.0;
    for (uint32_t j = 0; j < joints; ++j)
        deviation = std::max({deviation, double(angleBetween(states[j].rotation, cpu.states[j].rotation)),
                              double(angleBetween(poses[j].rotation, cpu.poses[j].rotation))});

    nlohmann::ordered_json out;
    out["joints"] = joints;
    out["steps"] = kSteps;
    out["max_deviation_rad"] = deviation;
    out["gpu_ms"] = gpuMs;
    out["cpu_ms"] = cpuMs;
    std::cout << out.dump() << std::endl;
    if (deviation < kMaxDeviationRad) return 0;
    std::cerr << "plantfield: error: GPU physics deviates from the CPU reference by " << deviation << " rad (limit "
              << kMaxDeviationRad << ")\n";
    return 1;
}

} // namespace pf
