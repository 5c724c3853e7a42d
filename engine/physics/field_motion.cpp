#include "engine/physics/field_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {
namespace {

// The shared copies and which each plant follows: `phases` copies per model,
// each plant the copy its wind phase falls in. Only the copies some plant
// follows are simulated, model after model and phase after phase; a copy no
// plant follows would be stepped for nothing (a scene of few plants).
struct SharedSkeletons {
    SkeletonSet set;
    std::vector<uint32_t> ofPlant; // index into set.skeletons
};

SharedSkeletons sharedSkeletons(const FieldContent& content) {
    const PlantModelPool& pool = content.models;
    const uint32_t phases = std::max(1u, content.scene.physics.sharedPhases);
    constexpr uint32_t kUnfollowed = ~0u;
    std::vector<uint32_t> copyOf(pool.models.size() * phases, kUnfollowed); // (model, phase) → skeleton
    SharedSkeletons shared;
    shared.ofPlant.resize(content.plants.size());
    for (size_t i = 0; i < content.plants.size(); ++i) {
        const PlantInstance& p = content.plants[i];
        const uint32_t phase =
            std::min(phases - 1, uint32_t(p.windPhase / (2.0f * std::numbers::pi_v<float>)*float(phases)));
        shared.ofPlant[i] = content.models.modelOf(p.species, p.variant) * phases + phase;
        copyOf[shared.ofPlant[i]] = 0;
    }
    const glm::vec3 along = windHeading(content.scene.wind);
    shared.set.params = pool.joints;
    for (uint32_t copy = 0; copy < copyOf.size(); ++copy) {
        if (copyOf[copy] == kUnfollowed) continue;
        copyOf[copy] = uint32_t(shared.set.skeletons.size());
        const uint32_t m = copy / phases, phase = copy % phases;
        addSkeleton(shared.set, m, pool.models[m].firstJoint, pool.models[m].joints,
                    along * (float(phase) * sharedPhaseSpacing(content.scene.physics)), 0.0f, 1.0f);
    }
    for (uint32_t& skeleton : shared.ofPlant) skeleton = copyOf[skeleton];
    return shared;
}

template <class T>
Buffer deviceCopyOf(GpuResources& owner, const std::vector<T>& data, VkBufferUsageFlags usage) {
    return createDeviceBufferWithData(owner, data.data(), data.size() * sizeof(T), usage);
}

void copyWhole(VkCommandBuffer cmd, const Buffer& from, const Buffer& to) {
    const VkBufferCopy region{0, 0, std::min(from.size, to.size)};
    vkCmdCopyBuffer(cmd, from.buffer, to.buffer, 1, &region);
}

// The near-plant changes of a frame: plants repointed (host-visible), own
// skeletons started from their shared copy's states and poses (copies the
// frame records).
void planNearChanges(FieldMotion& motion, const NearChanges& changes) {
    auto* skeletonOf = static_cast<uint32_t*>(motion.instanceSkeleton.mapped);
    for (const auto& [plant, skeleton] : changes.plantSkeleton) skeletonOf[plant] = skeleton;
    const auto* skeletons = static_cast<const gpu::Skeleton*>(motion.pass.skeletons.mapped);
    for (const auto& [own, shared] : changes.startFrom) {
        const uint32_t joints = skeletons[own].ids.z;
        motion.next.ownStates.push_back({skeletons[shared].ids.w * sizeof(gpu::JointState),
                                         skeletons[own].ids.w * sizeof(gpu::JointState),
                                         joints * sizeof(gpu::JointState)});
        motion.next.ownPoses.push_back({skeletons[shared].ids.w * sizeof(gpu::JointPose),
                                        skeletons[own].ids.w * sizeof(gpu::JointPose),
                                        joints * sizeof(gpu::JointPose)});
    }
}

} // namespace

float sharedPhaseSpacing(const PhysicsSettings& settings) {
    return kGustWavelength / float(std::max(1u, settings.sharedPhases));
}

FieldMotion createFieldMotion(GpuResources& owner, const FieldContent& content) {
    FieldMotion motion;
    motion.content = &content;
    motion.wind = content.scene.wind;
    motion.settings = content.scene.physics;
    SharedSkeletons shared = sharedSkeletons(content);
    SkeletonSet& set = shared.set;
    motion.near = reserveNearSkeletons(set, content.models, content.plants, motion.settings.jointBudget);
    motion.grid = makePlantGrid(content.plants, content.scene.terrain.size, 16.0f);
    motion.pass = createPhysicsPass(owner, set);
    motion.sharedOf = std::move(shared.ofPlant);
    motion.instanceSkeleton = createHostBuffer(owner, std::max<size_t>(1, motion.sharedOf.size()) * sizeof(uint32_t),
                                               VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    std::copy(motion.sharedOf.begin(), motion.sharedOf.end(), static_cast<uint32_t*>(motion.instanceSkeleton.mapped));
    motion.restStates = deviceCopyOf(owner, set.states, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    motion.restPoses = deviceCopyOf(owner, set.poses, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    return motion;
}

void advanceFieldMotion(FieldMotion& motion, double time, bool restart, const glm::vec3& camera, bool realTime) {
    motion.next = {};
    const double dt = motion.settings.subStep;
    // Whole sub-steps from time 0, so a time is reached the same way from anywhere.
    const uint64_t target = subStepsUntil(time, motion.settings);
    const bool farAhead = !realTime && target > motion.simulatedStep &&
                          target - motion.simulatedStep > subStepsUntil(kSettleSeconds, motion.settings);
    if (restart || target < motion.simulatedStep || farAhead) {
        motion.next.restart = true;
        motion.simulatedStep = subStepsUntil(std::max(0.0, time - kSettleSeconds), motion.settings);
        planNearChanges(motion, releaseAllNearSkeletons(motion.near, motion.sharedOf,
                                                        static_cast<gpu::Skeleton*>(motion.pass.skeletons.mapped)));
    }
    planNearChanges(motion, updateNearSkeletons(motion.near, motion.grid, motion.content->plants,
                                                motion.content->models, motion.sharedOf, camera,
                                                static_cast<gpu::Skeleton*>(motion.pass.skeletons.mapped)));
    if (realTime && !restart && target - motion.simulatedStep > kMaxFrameGapSubSteps)
        motion.simulatedStep = target - kMaxFrameGapSubSteps;
    const uint64_t steps = target - motion.simulatedStep;
    const double start = double(motion.simulatedStep) * dt;
    motion.next.subStepSeconds = dt;
    if (realTime && !motion.next.restart && steps > kFrameSubSteps) {
        // One dispatch of longer sub-steps (field_motion.h, kMaxFrameGapSubSteps).
        motion.next.subStepSeconds = dt * double(steps) / double(kFrameSubSteps);
        motion.next.dispatches.push_back({float(start), kFrameSubSteps});
        motion.simulatedStep = target;
    }
    // Frame-sized dispatches, so parents' poses are never older than kFrameSubSteps steps.
    for (uint64_t left = target - motion.simulatedStep; left > 0;) {
        const uint32_t count = uint32_t(std::min<uint64_t>(left, kFrameSubSteps));
        motion.next.dispatches.push_back({float(double(motion.simulatedStep) * dt), count});
        motion.simulatedStep += count;
        left -= count;
    }
    setPhysicsUniforms(motion.pass, makePhysicsUniforms(motion.wind, motion.settings, float(start),
                                                        float(motion.next.subStepSeconds), 0, motion.pass.skeletonCount,
                                                        motion.pass.jointCount));
}

void recordFieldMotion(VkCommandBuffer cmd, const FieldMotion& motion, GpuTimer* timer) {
    const FieldMotionFrame& frame = motion.next;
    if (frame.restart || !frame.ownStates.empty()) {
        // The copies overwrite states and poses the previous frame's passes
        // wrote and its vertex shaders read (write-after-write and -read).
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
    }
    if (frame.restart) {
        copyWhole(cmd, motion.restStates, motion.pass.states);
        copyWhole(cmd, motion.restPoses, motion.pass.poses);
    }
    if (!frame.ownStates.empty()) {
        // Own skeletons start from their shared copy's state, rest included.
        if (frame.restart)
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
        // Within one buffer: source and destination ranges never overlap (different skeletons).
        vkCmdCopyBuffer(cmd, motion.pass.states.buffer, motion.pass.states.buffer, uint32_t(frame.ownStates.size()),
                        frame.ownStates.data());
        vkCmdCopyBuffer(cmd, motion.pass.poses.buffer, motion.pass.poses.buffer, uint32_t(frame.ownPoses.size()),
                        frame.ownPoses.data());
    }
    if (frame.restart || !frame.ownStates.empty()) {
        // The physics and pose passes read and overwrite what was copied.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    recordPhysicsPass(cmd, motion.pass, frame.dispatches, timer);
}

} // namespace pf
