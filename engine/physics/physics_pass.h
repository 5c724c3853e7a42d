// The physics and pose passes on the GPU, the frame's first two (before the
// cull pass): one compute invocation per simulated joint takes the frame's sub-steps
// (shaders/physics.comp), then the poses are composed level by level from
// the roots, one dispatch per depth (shaders/pose.comp). The poses are what the vertex
// shaders skin plant vertices with. engine/physics/plant_physics.h is the CPU
// reference of both.
#pragma once

#include "engine/physics/plant_physics.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/gpu_timer.h"
#include "engine/vk/resources.h"

#include <array>
#include <span>
#include <vector>

namespace pf {

struct PhysicsPass {
    ComputeSet set; // PHYSICS_BINDING_*: the buffers below; its pipeline layout has the pose level's push constants
    // physics.comp for 1, 2, … PHYSICS_MAX_DISPATCH_SUB_STEPS sub-steps (index count − 1).
    std::array<VkPipeline, PHYSICS_MAX_DISPATCH_SUB_STEPS> physicsPipelines{};
    VkPipeline posePipeline = VK_NULL_HANDLE;

    Buffer uniforms;      // host-visible PhysicsUniforms
    Buffer params;        // JointParams[]
    Buffer skeletons;     // Skeleton[] (host-visible: near plants' skeletons move with them)
    Buffer states;        // JointState[]
    Buffer poses;         // JointPose[] (read by the vertex shaders)
    Buffer jointSkeleton; // uint per simulated joint
    Buffer jointOrder;    // uint per simulated joint: the joints level after level (depth 0 first)

    uint32_t skeletonCount = 0;
    uint32_t jointCount = 0;
    uint32_t maxGroupsX = 0;        // maxComputeWorkGroupCount[0]: longer dispatches wrap into rows
    std::vector<glm::uvec2> levels; // per depth: x first entry of jointOrder, y joints
};

// Uploads the set (its states and poses as they are, normally at rest).
// What the pass creates is owned by `owner`.
PhysicsPass createPhysicsPass(GpuResources& owner, const SkeletonSet& set);

// Per frame, while no frame using them is in flight. Each dispatch replaces
// the time (windDetail.z) and sub-step count (counts.z) with its own.
void setPhysicsUniforms(const PhysicsPass& pass, const gpu::PhysicsUniforms& uniforms);

// The timer scopes recordPhysicsPass records (engine/field/field_scopes.h
// lists them among the frame's).
inline constexpr const char* kPhysicsScope = "physics";
inline constexpr const char* kPoseScope = "pose";

// Records, for each dispatch in order, its physics sub-steps (none when 0,
// at most PHYSICS_MAX_DISPATCH_SUB_STEPS, else std::invalid_argument)
// then the pose levels, with the barriers that order the first after the
// previous frame's vertex reads of the poses, each dispatch after the poses
// of the one before, and make the last poses visible to vertex shaders. With
// a timer, everything up to the last pose levels is scope kPhysicsScope and
// those are kPoseScope (both recorded unless the set is empty). No dispatch at all
// poses once. Compute only: record it outside rendering.
void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass, std::span<const gpu::PhysicsDispatch> dispatches,
                       GpuTimer* timer = nullptr);
// One dispatch at the time and sub-step count setPhysicsUniforms wrote.
void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass, GpuTimer* timer = nullptr);

// Copies states and poses back (tests, --physics-check).
void readPhysicsState(const GpuContext& ctx, const PhysicsPass& pass, std::vector<gpu::JointState>& states,
                      std::vector<gpu::JointPose>& poses);

} // namespace pf
