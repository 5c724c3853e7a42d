// The physics and pose passes on the GPU (DESIGN.md §5 passes 1 and 2):
// one compute invocation per simulated joint takes the frame's sub-steps
// (shaders/physics.comp), then the poses are composed level by level from
// the roots, one dispatch per depth (shaders/pose.comp). The poses are what the vertex
// shaders skin plant vertices with. engine/physics/plant_physics.h is the CPU
// reference of both.
#pragma once

#include "engine/physics/plant_physics.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/gpu_timer.h"
#include "engine/vk/resources.h"

#include <vector>

namespace pf {

struct PhysicsPass {
    ComputeSet set; // PHYSICS_BINDING_*: the buffers below; its pipeline layout has the pose level's push constants
    VkPipeline physicsPipeline = VK_NULL_HANDLE;
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

// Per frame, while no frame using them is in flight.
void setPhysicsUniforms(const PhysicsPass& pass, const gpu::PhysicsUniforms& uniforms);

// Records physics (u.counts.z sub-steps; none when 0) then pose, with the
// barriers that order them after the previous frame's vertex reads of the
// poses and make the new poses visible to vertex shaders. With a timer, the
// physics dispatch is timed as scope "physics" and the pose levels as
// "pose" (both recorded unless the set is empty; "physics" times nothing
// when there are no sub-steps). Compute only: record it outside rendering.
void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass, GpuTimer* timer = nullptr);

// Copies states and poses back (tests, --physics-check).
void readPhysicsState(const GpuContext& ctx, const PhysicsPass& pass, std::vector<gpu::JointState>& states,
                      std::vector<gpu::JointPose>& poses);

} // namespace pf
