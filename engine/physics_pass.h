// The physics and pose passes on the GPU (DESIGN.md §5 passes 1 and 2):
// one compute invocation per simulated joint takes the frame's sub-steps
// (shaders/physics.comp), then one per joint composes its pose from its
// ancestors' rotations (shaders/pose.comp). The poses are what the vertex
// shaders skin plant vertices with. engine/plant_physics.h is the CPU
// reference of both.
#pragma once

#include "engine/plant_physics.h"
#include "engine/compute_set.h"
#include "engine/resources.h"

namespace pf {

struct PhysicsPass {
    ComputeSet set; // uniforms, then the storage buffers below
    VkPipeline physicsPipeline = VK_NULL_HANDLE;
    VkPipeline posePipeline = VK_NULL_HANDLE;

    Buffer uniforms;      // host-visible PhysicsUniforms
    Buffer params;        // JointParams[]
    Buffer skeletons;     // Skeleton[] (host-visible: near plants' skeletons move with them)
    Buffer states;        // JointState[]
    Buffer poses;         // JointPose[] (read by the vertex shaders)
    Buffer jointSkeleton; // uint per simulated joint

    uint32_t skeletonCount = 0;
    uint32_t jointCount = 0;
    glm::uvec2 groups{}; // physics and pose dispatches: rows of at most maxComputeWorkGroupCount[0] groups
};

// Uploads the set (its states and poses as they are, normally at rest).
PhysicsPass createPhysicsPass(const GpuContext& ctx, const SkeletonSet& set);
void destroyPhysicsPass(const GpuContext& ctx, PhysicsPass& pass);

// Per frame, while no frame using them is in flight.
void setPhysicsUniforms(const PhysicsPass& pass, const gpu::PhysicsUniforms& uniforms);

// Records physics (u.counts.z sub-steps; none when 0) then pose, with the
// barriers that order them after the previous frame's vertex reads of the
// poses and make the new poses visible to vertex shaders.
void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass);

// Copies states and poses back (tests, --physics-check).
void readPhysicsState(const GpuContext& ctx, const PhysicsPass& pass, std::vector<gpu::JointState>& states,
                      std::vector<gpu::JointPose>& poses);

} // namespace pf
