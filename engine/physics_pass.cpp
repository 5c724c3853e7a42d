#include "engine/physics_pass.h"

#include "engine/pipeline.h"
#include "engine/vk_check.h"

#include "shaders/physics_comp.spv.h"
#include "shaders/pose_comp.spv.h"

#include <algorithm>
#include <cstring>

namespace pf {

namespace {

// Binding order of shaders/physics.comp and shaders/pose.comp.
enum Binding : uint32_t {
    kBindingUniforms,
    kBindingParams,
    kBindingSkeletons,
    kBindingStates,
    kBindingPoses,
    kBindingJointSkeleton,
    kBindingCount
};

// Buffers of zero size are invalid: an empty set still gets one element each.
template <typename T>
VkDeviceSize bytesOf(const std::vector<T>& v) {
    return VkDeviceSize(std::max<size_t>(v.size(), 1)) * sizeof(T);
}

// Past maxComputeWorkGroupCount[0] groups a dispatch wraps into rows.
glm::uvec2 dispatchGroups(const PhysicsPass& pass, const GpuContext& ctx) {
    const uint32_t groups = (pass.jointCount + PHYSICS_GROUP_SIZE - 1) / PHYSICS_GROUP_SIZE;
    const uint32_t x = std::min(groups, ctx.properties.limits.maxComputeWorkGroupCount[0]);
    return {x, x ? (groups + x - 1) / x : 0};
}

} // namespace

PhysicsPass createPhysicsPass(const GpuContext& ctx, const SkeletonSet& set) {
    PhysicsPass pass;
    pass.skeletonCount = uint32_t(set.skeletons.size());
    pass.jointCount = uint32_t(set.states.size());
    pass.groups = dispatchGroups(pass, ctx);

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkBufferUsageFlags uploaded = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    pass.uniforms = createHostBuffer(ctx, sizeof(gpu::PhysicsUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    pass.skeletons = createHostBuffer(ctx, bytesOf(set.skeletons), storage);
    if (!set.skeletons.empty())
        std::memcpy(pass.skeletons.mapped, set.skeletons.data(), set.skeletons.size() * sizeof(gpu::Skeleton));
    std::memset(pass.uniforms.mapped, 0, sizeof(gpu::PhysicsUniforms));

    pass.params = createBuffer(ctx, bytesOf(set.params), uploaded, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.states = createBuffer(ctx, bytesOf(set.states), uploaded | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.poses = createBuffer(ctx, bytesOf(set.poses), uploaded | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.jointSkeleton = createBuffer(ctx, bytesOf(set.jointSkeleton), uploaded, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

    // One staging buffer holds the four device-local arrays back to back.
    struct Upload {
        const void* data;
        VkDeviceSize bytes;
        const Buffer* target;
    };
    const Upload uploads[] = {
        {set.params.data(), set.params.size() * sizeof(gpu::JointParams), &pass.params},
        {set.states.data(), set.states.size() * sizeof(gpu::JointState), &pass.states},
        {set.poses.data(), set.poses.size() * sizeof(gpu::JointPose), &pass.poses},
        {set.jointSkeleton.data(), set.jointSkeleton.size() * sizeof(uint32_t), &pass.jointSkeleton}};
    VkDeviceSize stagingBytes = 0;
    for (const Upload& u : uploads) stagingBytes += u.bytes;
    if (stagingBytes > 0) {
        Buffer staging = createHostBuffer(ctx, stagingBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            VkDeviceSize offset = 0;
            for (const Upload& u : uploads) {
                if (u.bytes == 0) continue;
                std::memcpy(static_cast<char*>(staging.mapped) + offset, u.data, u.bytes);
                const VkBufferCopy region{offset, 0, u.bytes};
                vkCmdCopyBuffer(cmd, staging.buffer, u.target->buffer, 1, &region);
                offset += u.bytes;
            }
            // Waiting for the queue is no memory dependency: the first
            // physics and pose dispatches read (and overwrite) these.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        });
        destroyBuffer(ctx, staging);
    }

    const VkBuffer buffers[kBindingCount] = {pass.uniforms.buffer, pass.params.buffer, pass.skeletons.buffer,
                                             pass.states.buffer,   pass.poses.buffer,  pass.jointSkeleton.buffer};
    pass.set = createComputeSet(ctx, buffers);
    pass.physicsPipeline =
        createComputePipeline(ctx.device, pass.set.pipelineLayout, createShaderModule(ctx.device, spirv_physics_comp));
    pass.posePipeline =
        createComputePipeline(ctx.device, pass.set.pipelineLayout, createShaderModule(ctx.device, spirv_pose_comp));
    return pass;
}

void destroyPhysicsPass(const GpuContext& ctx, PhysicsPass& pass) {
    vkDestroyPipeline(ctx.device, pass.physicsPipeline, nullptr);
    vkDestroyPipeline(ctx.device, pass.posePipeline, nullptr);
    destroyComputeSet(ctx, pass.set);
    for (Buffer* b : {&pass.uniforms, &pass.params, &pass.skeletons, &pass.states, &pass.poses, &pass.jointSkeleton})
        destroyBuffer(ctx, *b);
    pass = {};
}

void setPhysicsUniforms(const PhysicsPass& pass, const gpu::PhysicsUniforms& uniforms) {
    // The shaders bound their invocations by the counts of the buffers they were given.
    gpu::PhysicsUniforms u = uniforms;
    u.counts.x = pass.skeletonCount;
    u.counts.y = pass.jointCount;
    std::memcpy(pass.uniforms.mapped, &u, sizeof(u));
}

void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass) {
    // The previous frame's vertex shaders may still read the poses the pose
    // dispatch overwrites (write-after-read: execution only), and the
    // previous physics and pose dispatches wrote the states and poses read
    // here (read-after-write: make them visible).
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    if (pass.jointCount == 0) return;

    bindComputeSet(cmd, pass.set);
    // The sub-step count is what setPhysicsUniforms wrote for this frame.
    const uint32_t subSteps = static_cast<const gpu::PhysicsUniforms*>(pass.uniforms.mapped)->counts.z;
    if (subSteps > 0) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.physicsPipeline);
        vkCmdDispatch(cmd, pass.groups.x, pass.groups.y, 1);
        // The pose dispatch reads the new states, and overwrites the poses
        // the physics dispatch read (write-after-read, covered by the same
        // execution dependency).
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.posePipeline);
    vkCmdDispatch(cmd, pass.groups.x, pass.groups.y, 1);
    // The vertex shaders skin plant vertices with the new poses.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void readPhysicsState(const GpuContext& ctx, const PhysicsPass& pass, std::vector<gpu::JointState>& states,
                      std::vector<gpu::JointPose>& poses) {
    states.resize(pass.jointCount);
    poses.resize(pass.jointCount);
    if (pass.jointCount == 0) return;
    const VkDeviceSize stateBytes = VkDeviceSize(pass.jointCount) * sizeof(gpu::JointState);
    const VkDeviceSize poseBytes = VkDeviceSize(pass.jointCount) * sizeof(gpu::JointPose);
    Buffer readback = createHostBuffer(ctx, stateBytes + poseBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        // The last physics and pose dispatches wrote what is copied.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        const VkBufferCopy stateRegion{0, 0, stateBytes};
        const VkBufferCopy poseRegion{0, stateBytes, poseBytes};
        vkCmdCopyBuffer(cmd, pass.states.buffer, readback.buffer, 1, &stateRegion);
        vkCmdCopyBuffer(cmd, pass.poses.buffer, readback.buffer, 1, &poseRegion);
        // The host reads the copy after the queue is idle.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    });
    std::memcpy(states.data(), readback.mapped, stateBytes);
    std::memcpy(poses.data(), static_cast<const char*>(readback.mapped) + stateBytes, poseBytes);
    destroyBuffer(ctx, readback);
}

} // namespace pf
