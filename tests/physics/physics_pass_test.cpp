// The physics and pose compute passes (engine/physics/physics_pass.h) against their
// CPU reference (engine/physics/plant_physics.h stepSkeletonsOnCpu and
// poseSkeletonsOnCpu) on a synthetic forest; every GPU test runs with the
// validation layer on.
#include "engine/physics/physics_pass.h"
#include "gpu_test.h"
#include "shaders/shared/joint_physics.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace pf {
namespace {

constexpr float kPi = 3.14159265f;
constexpr uint32_t kStepsPerFrame = 8;

glm::vec4 toVec4(const glm::quat& q) { return glm::vec4(q.x, q.y, q.z, q.w); }

// A model's skeleton built segment by segment: each segment starts at the
// tip of its parent and is its parent's frame turned by `bend`.
struct ModelBuilder {
    std::vector<gpu::JointParams> joints;

    uint32_t add(uint32_t parent, const glm::quat& bend, float length, float radius, float leafArea) {
        glm::vec3 base(0.0f);
        glm::quat parentFrame(1, 0, 0, 0);
        uint32_t depth = 0;
        if (parent != JOINT_NO_PARENT) {
            const gpu::JointParams& p = joints[parent];
            parentFrame = glm::quat(p.restRotation.w, p.restRotation.x, p.restRotation.y, p.restRotation.z);
            base = glm::vec3(p.restBase) + parentFrame * glm::vec3(0, p.restBase.w, 0);
            depth = p.links.y + 1;
        }
        // Green wood with a soft Young's modulus so twigs visibly flex.
        const float mass = 600.0f * kPi * radius * radius * length;
        const float inertia = mass * length * length / 3.0f;
        const float stiffness = 2.0e8f * kPi * radius * radius * radius * radius / (4.0f * length);
        gpu::JointParams jp{};
        jp.restBase = glm::vec4(base, length);
        jp.restRotation = toVec4(glm::normalize(parentFrame * bend));
        jp.dynamics = glm::vec4(mass, inertia, stiffness, 2.0f * 0.15f * std::sqrt(stiffness * inertia));
        jp.aero = glm::vec4(2.0f * radius * length + leafArea, 0.6f * length, 0, 0);
        jp.links = glm::uvec4(parent, depth, 0, 0);
        joints.push_back(jp);
        return uint32_t(joints.size() - 1);
    }

    // Subtree loads: mass and centre of mass of each joint and its
    // descendants, relative to the joint's base in its rest frame.
    std::vector<gpu::JointParams> finish() {
        const size_t n = joints.size();
        std::vector<glm::vec3> moment(n, glm::vec3(0.0f));
        std::vector<float> mass(n, 0.0f);
        for (size_t j = n; j-- > 0;) { // children come after their parents
            const gpu::JointParams& jp = joints[j];
            const glm::quat r(jp.restRotation.w, jp.restRotation.x, jp.restRotation.y, jp.restRotation.z);
            const glm::vec3 centre = glm::vec3(jp.restBase) + r * glm::vec3(0, 0.5f * jp.restBase.w, 0);
            moment[j] += jp.dynamics.x * centre;
            mass[j] += jp.dynamics.x;
            const glm::vec3 com = moment[j] / mass[j];
            joints[j].load = glm::vec4(glm::inverse(r) * (com - glm::vec3(jp.restBase)), mass[j]);
            if (jp.links.x != JOINT_NO_PARENT) {
                moment[jp.links.x] += moment[j];
                mass[jp.links.x] += mass[j];
            }
        }
        return joints;
    }
};

glm::quat bend(float degrees, glm::vec3 axis) { return glm::angleAxis(glm::radians(degrees), glm::normalize(axis)); }

// A leaning chain of six segments.
std::vector<gpu::JointParams> chainModel() {
    ModelBuilder b;
    uint32_t j = b.add(JOINT_NO_PARENT, bend(8, {0, 0, 1}), 0.9f, 0.05f, 0.0f);
    for (int i = 1; i < 6; ++i)
        j = b.add(j, bend(10, {0.3f, 0, 1}), 0.9f - 0.12f * float(i), 0.05f - 0.007f * float(i), 0.02f * float(i));
    return b.finish();
}

// A trunk of three segments, each carrying two branches of three segments
// with a leafy twig on their second: seven levels deep.
std::vector<gpu::JointParams> treeModel() {
    ModelBuilder b;
    uint32_t trunk = b.add(JOINT_NO_PARENT, bend(2, {1, 0, 0}), 1.5f, 0.12f, 0.0f);
    for (int level = 0; level < 3; ++level) {
        for (int side = 0; side < 2; ++side) {
            const glm::vec3 axis = side ? glm::vec3(1, 0, 0.2f * float(level)) : glm::vec3(-0.3f, 0, 1);
            uint32_t branch = b.add(trunk, bend(35.0f + 5.0f * float(level), axis), 0.8f, 0.035f, 0.0f);
            for (int k = 0; k < 2; ++k) {
                branch = b.add(branch, bend(-12, axis), 0.6f, 0.022f - 0.006f * float(k), 0.05f);
                if (k == 0) b.add(branch, bend(50, {0, 0.2f, 1}), 0.3f, 0.008f, 0.12f);
            }
        }
        if (level < 2)
            trunk = b.add(trunk, bend(4, {0, 0, 1}), 1.2f - 0.3f * float(level), 0.1f - 0.025f * float(level), 0.0f);
    }
    return b.finish();
}

// A single leaning blade.
std::vector<gpu::JointParams> bladeModel() {
    ModelBuilder b;
    b.add(JOINT_NO_PARENT, bend(15, {1, 0, 1}), 0.5f, 0.006f, 0.01f);
    return b.finish();
}

// Every model once, then `copies` skeletons of each, spread over 40 m
// (so gust fronts reach them at different times) with yaws and scales.
SkeletonSet makeForest(uint32_t copies) {
    SkeletonSet set;
    std::vector<glm::uvec2> models; // first param, joints
    for (const auto& model : {chainModel(), treeModel(), bladeModel()}) {
        models.push_back({uint32_t(set.params.size()), uint32_t(model.size())});
        set.params.insert(set.params.end(), model.begin(), model.end());
    }
    for (uint32_t c = 0; c < copies; ++c)
        for (uint32_t m = 0; m < models.size(); ++m) {
            const uint32_t i = c * uint32_t(models.size()) + m;
            const glm::vec3 position(std::fmod(13.7f * float(i), 40.0f) - 20.0f, 0.1f * float(m),
                                     std::fmod(7.3f * float(i), 40.0f) - 20.0f);
            addSkeleton(set, m, models[m].x, models[m].y, position, 0.7f * float(i), 0.7f + 0.15f * float(i % 5));
        }
    return set;
}

Wind gustyWind() {
    Wind wind;
    wind.speed = 9.0f;
    wind.directionDegrees = 75.0f;
    wind.gustStrength = 1.0f;
    wind.gustSpeed = 7.0f;
    wind.turbulence = 0.4f;
    return wind;
}

float angleBetween(const glm::vec4& a, const glm::vec4& b) {
    return glm::length(gpu::rotationVectorOf(gpu::quatMultiply(a, gpu::quatConjugate(b))));
}

void runFrame(const GpuContext& ctx, const PhysicsPass& pass, const gpu::PhysicsUniforms& u) {
    setPhysicsUniforms(pass, u);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordPhysicsPass(cmd, pass); });
}

class PhysicsPassTest : public test::GpuTest {};

TEST_F(PhysicsPassTest, MatchesCpuReferenceAfter600SubStepsInGustyWind) {
    SkeletonSet cpu = makeForest(4);
    ASSERT_GT(cpu.states.size(), 100u);
    PhysicsPass pass = createPhysicsPass(resources, cpu);
    const Wind wind = gustyWind();
    const PhysicsSettings settings;
    const uint32_t joints = uint32_t(cpu.states.size()), skeletons = uint32_t(cpu.skeletons.size());

    for (uint32_t frame = 0; frame < 600 / kStepsPerFrame; ++frame) {
        const float time = float(frame * kStepsPerFrame) * settings.subStep;
        const gpu::PhysicsUniforms u =
            makePhysicsUniforms(wind, settings, time, settings.subStep, kStepsPerFrame, skeletons, joints);
        stepSkeletonsOnCpu(cpu, u);
        poseSkeletonsOnCpu(cpu);
        runFrame(ctx, pass, u);
    }
    std::vector<gpu::JointState> states;
    std::vector<gpu::JointPose> poses;
    readPhysicsState(ctx, pass, states, poses);
    ASSERT_EQ(states.size(), joints);

    float stateDeviation = 0, poseDeviation = 0, translationDeviation = 0, largestBend = 0;
    for (uint32_t j = 0; j < joints; ++j) {
        stateDeviation = std::max(stateDeviation, angleBetween(states[j].rotation, cpu.states[j].rotation));
        poseDeviation = std::max(poseDeviation, angleBetween(poses[j].rotation, cpu.poses[j].rotation));
        translationDeviation = std::max(
            translationDeviation, glm::length(glm::vec3(poses[j].translation) - glm::vec3(cpu.poses[j].translation)));
        largestBend = std::max(largestBend, glm::length(gpu::rotationVectorOf(cpu.states[j].rotation)));
    }
    std::printf(
        "%u joints: deviation %.3g rad (states), %.3g rad (poses), %.3g m (translations); largest bend %.3g rad\n",
        joints, stateDeviation, poseDeviation, translationDeviation, largestBend);
    EXPECT_GT(largestBend, 0.02f) << "the wind should move the forest";
    EXPECT_LT(stateDeviation, 1e-4f);
    EXPECT_LT(poseDeviation, 1e-4f);
    EXPECT_LT(translationDeviation, 1e-4f * 10.0f); // 1e-4 rad over plants under 10 m
}

// Each sub-step count has a pipeline of its own (physics_layouts.h): every
// one of them, in one command buffer, against the CPU reference.
TEST_F(PhysicsPassTest, DispatchesOfEverySubStepCountMatchTheCpuReference) {
    SkeletonSet cpu = makeForest(2);
    PhysicsPass pass = createPhysicsPass(resources, cpu);
    const Wind wind = gustyWind();
    const PhysicsSettings settings;
    const uint32_t joints = uint32_t(cpu.states.size()), skeletons = uint32_t(cpu.skeletons.size());
    std::vector<gpu::PhysicsDispatch> dispatches;
    uint32_t step = 0;
    for (uint32_t round = 0; round < 4; ++round)
        for (uint32_t count = 1; count <= PHYSICS_MAX_DISPATCH_SUB_STEPS; ++count) {
            dispatches.push_back({float(step) * settings.subStep, count});
            step += count;
        }
    setPhysicsUniforms(pass, makePhysicsUniforms(wind, settings, 0.0f, settings.subStep, 0, skeletons, joints));
    submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordPhysicsPass(cmd, pass, dispatches); });
    for (const gpu::PhysicsDispatch& d : dispatches) {
        stepSkeletonsOnCpu(
            cpu, makePhysicsUniforms(wind, settings, d.time, settings.subStep, d.subSteps, skeletons, joints));
        poseSkeletonsOnCpu(cpu);
    }
    std::vector<gpu::JointState> states;
    std::vector<gpu::JointPose> poses;
    readPhysicsState(ctx, pass, states, poses);
    ASSERT_EQ(states.size(), joints);
    float deviation = 0, largestBend = 0;
    for (uint32_t j = 0; j < joints; ++j) {
        deviation = std::max(deviation, angleBetween(poses[j].rotation, cpu.poses[j].rotation));
        largestBend = std::max(largestBend, glm::length(gpu::rotationVectorOf(cpu.states[j].rotation)));
    }
    std::printf("%zu dispatches, %u sub-steps: pose deviation %.3g rad, largest bend %.3g rad\n", dispatches.size(),
                step, deviation, largestBend);
    EXPECT_GT(largestBend, 0.02f) << "the wind should move the forest";
    EXPECT_LT(deviation, 1e-4f);
}

TEST_F(PhysicsPassTest, DispatchOfMoreSubStepsThanAPipelineTakesIsRefused) {
    PhysicsPass pass = createPhysicsPass(resources, makeForest(1));
    const gpu::PhysicsDispatch tooLong{0.0f, PHYSICS_MAX_DISPATCH_SUB_STEPS + 1};
    VkCommandBuffer cmd = allocateCommandBuffer(ctx);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &begin);
    EXPECT_THROW(recordPhysicsPass(cmd, pass, {&tooLong, 1}), std::invalid_argument);
    vkEndCommandBuffer(cmd);
    vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
}

TEST_F(PhysicsPassTest, RestInRestOutWithZeroSubSteps) {
    SkeletonSet cpu = makeForest(2);
    PhysicsPass pass = createPhysicsPass(resources, cpu);
    const uint32_t joints = uint32_t(cpu.states.size());
    runFrame(ctx, pass,
             makePhysicsUniforms(gustyWind(), PhysicsSettings{}, 3.0f, 1.0f / 240.0f, 0, uint32_t(cpu.skeletons.size()),
                                 joints));
    poseSkeletonsOnCpu(cpu);
    std::vector<gpu::JointState> states;
    std::vector<gpu::JointPose> poses;
    readPhysicsState(ctx, pass, states, poses);
    ASSERT_EQ(states.size(), joints);
    for (uint32_t j = 0; j < joints; ++j) {
        EXPECT_EQ(states[j].rotation, glm::vec4(0, 0, 0, 1)) << "joint " << j;
        EXPECT_EQ(states[j].angularVelocity, glm::vec4(0)) << "joint " << j;
        EXPECT_LT(angleBetween(poses[j].rotation, glm::vec4(0, 0, 0, 1)), 1e-6f) << "joint " << j;
        EXPECT_LT(glm::length(glm::vec3(poses[j].translation)), 1e-5f) << "joint " << j;
        EXPECT_LT(angleBetween(poses[j].rotation, cpu.poses[j].rotation), 1e-6f) << "joint " << j;
    }
}

TEST_F(PhysicsPassTest, EmptySetRecordsNothing) {
    PhysicsPass pass = createPhysicsPass(resources, SkeletonSet{});
    runFrame(ctx, pass, makePhysicsUniforms(gustyWind(), PhysicsSettings{}, 0.0f, 1.0f / 240.0f, kStepsPerFrame, 0, 0));
    std::vector<gpu::JointState> states(3);
    std::vector<gpu::JointPose> poses(3);
    readPhysicsState(ctx, pass, states, poses);
    EXPECT_TRUE(states.empty());
    EXPECT_TRUE(poses.empty());
}

TEST_F(PhysicsPassTest, MillionJointsDispatchRuns) {
    SkeletonSet set;
    set.params = treeModel();
    const uint32_t perTree = uint32_t(set.params.size());
    const uint32_t trees = (1000000 + perTree - 1) / perTree;
    for (uint32_t t = 0; t < trees; ++t)
        addSkeleton(set, 0, 0, perTree, glm::vec3(float(t % 1000), 0, float(t / 1000)), 0.1f * float(t), 1.0f);
    const uint32_t joints = uint32_t(set.states.size());
    ASSERT_GE(joints, 1000000u);
    PhysicsPass pass = createPhysicsPass(resources, set);
    const gpu::PhysicsUniforms u =
        makePhysicsUniforms(gustyWind(), PhysicsSettings{}, 0.0f, 1.0f / 240.0f, kStepsPerFrame, trees, joints);
    runFrame(ctx, pass, u); // pipelines warm up
    const auto start = std::chrono::steady_clock::now();
    runFrame(ctx, pass, u);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%u joints, %u sub-steps + pose: %.1f ms (submit and wait)\n", joints, kStepsPerFrame, ms);
    std::vector<gpu::JointState> states;
    std::vector<gpu::JointPose> poses;
    readPhysicsState(ctx, pass, states, poses);
    ASSERT_EQ(states.size(), joints);
    for (uint32_t j = 0; j < joints; j += 997) {
        ASSERT_TRUE(std::isfinite(states[j].rotation.x) && std::isfinite(poses[j].translation.y)) << "joint " << j;
        ASSERT_NEAR(glm::length(states[j].rotation), 1.0f, 1e-5f) << "joint " << j;
    }
}

} // namespace
} // namespace pf
