#include "engine/physics/physics_pass.h"

#include "engine/vk/pipeline.h"

#include "shaders/physics_comp.spv.h"
#include "shaders/pose_comp.spv.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace pf {

namespace {

// What the passes read: shader reads of storage buffers and of the texel
// views of shaders/physics_bindings.glsl.
constexpr VkAccessFlags2 kShaderReads = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

// Buffers of zero size are invalid: an empty set still gets one element each.
template <typename T>
VkDeviceSize bytesOf(const std::vector<T>& v) {
    return VkDeviceSize(std::max<size_t>(v.size(), 1)) * sizeof(T);
}

// Past maxComputeWorkGroupCount[0] groups a dispatch wraps into rows.
void dispatchJoints(VkCommandBuffer cmd, const PhysicsPass& pass, uint32_t joints) {
    const uint32_t groups = (joints + PHYSICS_GROUP_SIZE - 1) / PHYSICS_GROUP_SIZE;
    const uint32_t x = std::min(groups, pass.maxGroupsX);
    vkCmdDispatch(cmd, x, (groups + x - 1) / x, 1);
}

// The simulated joints grouped by depth (a counting sort on links.y), and
// each depth's run of them: what the pose levels dispatch over.
std::vector<uint32_t> jointsByDepth(const SkeletonSet& set, std::vector<glm::uvec2>& levels) {
    const size_t n = set.states.size();
    std::vector<uint32_t> depth(n);
    levels.clear();
    for (size_t i = 0; i < n; ++i) {
        const gpu::Skeleton& skeleton = set.skeletons[set.jointSkeleton[i]];
        depth[i] = set.params[skeleton.ids.y + (uint32_t(i) - skeleton.ids.w)].links.y;
        if (depth[i] >= levels.size()) levels.resize(depth[i] + 1, glm::uvec2(0));
        ++levels[depth[i]].y;
    }
    for (size_t d = 1; d < levels.size(); ++d) levels[d].x = levels[d - 1].x + levels[d - 1].y;
    std::vector<uint32_t> order(n);
    std::vector<uint32_t> next(levels.size());
    for (size_t d = 0; d < levels.size(); ++d) next[d] = levels[d].x;
    for (size_t i = 0; i < n; ++i) order[next[depth[i]]++] = uint32_t(i);
    return order;
}

// The dispatch's sub-steps of every joint, then the barrier that lets the
// pose levels read the new states and overwrite the poses it read.
void recordPhysicsDispatch(VkCommandBuffer cmd, const PhysicsPass& pass, const gpu::PhysicsDispatch& dispatch) {
    if (dispatch.subSteps == 0) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.physicsPipelines[dispatch.subSteps - 1]);
    vkCmdPushConstants(cmd, pass.set.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(dispatch), &dispatch);
    dispatchJoints(cmd, pass, pass.jointCount);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kShaderReads | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

// Every pose from the roots down, one dispatch per depth.
void recordPoseLevels(VkCommandBuffer cmd, const PhysicsPass& pass) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.posePipeline);
    for (size_t d = 0; d < pass.levels.size(); ++d) {
        if (d > 0) {
            // This level reads the poses of its parents, which the previous level wrote.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kShaderReads);
        }
        const glm::uvec2 level = pass.levels[d]; // never empty: a joint at depth d > 0 has a parent at d − 1
        vkCmdPushConstants(cmd, pass.set.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(level), &level);
        dispatchJoints(cmd, pass, level.y);
    }
}

} // namespace

PhysicsPass createPhysicsPass(GpuResources& owner, const SkeletonSet& set) {
    const GpuContext& ctx = owner.ctx();
    PhysicsPass pass;
    pass.skeletonCount = uint32_t(set.skeletons.size());
    pass.jointCount = uint32_t(set.states.size());
    pass.maxGroupsX = ctx.properties.limits.maxComputeWorkGroupCount[0];
    const std::vector<uint32_t> order = jointsByDepth(set, pass.levels);

    // Every array is read through a texel view; states and poses are also written.
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    const VkBufferUsageFlags uploaded = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    pass.uniforms = createHostBuffer(owner, sizeof(gpu::PhysicsUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pass.skeletons = createHostBuffer(owner, bytesOf(set.skeletons), storage);
    if (!set.skeletons.empty())
        std::memcpy(pass.skeletons.mapped, set.skeletons.data(), set.skeletons.size() * sizeof(gpu::Skeleton));
    std::memset(pass.uniforms.mapped, 0, sizeof(gpu::PhysicsUniforms));

    pass.params = createBuffer(owner, bytesOf(set.params), uploaded, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.states = createBuffer(owner, bytesOf(set.states), uploaded | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.poses = createBuffer(owner, bytesOf(set.poses), uploaded | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.jointSkeleton = createBuffer(owner, bytesOf(set.jointSkeleton), uploaded, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    pass.jointOrder = createBuffer(owner, bytesOf(order), uploaded, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

    // One staging buffer holds the five device-local arrays back to back.
    struct Upload {
        const void* data;
        VkDeviceSize bytes;
        const Buffer* target;
    };
    const Upload uploads[] = {
        {set.params.data(), set.params.size() * sizeof(gpu::JointParams), &pass.params},
        {set.states.data(), set.states.size() * sizeof(gpu::JointState), &pass.states},
        {set.poses.data(), set.poses.size() * sizeof(gpu::JointPose), &pass.poses},
        {set.jointSkeleton.data(), set.jointSkeleton.size() * sizeof(uint32_t), &pass.jointSkeleton},
        {order.data(), order.size() * sizeof(uint32_t), &pass.jointOrder}};
    VkDeviceSize stagingBytes = 0;
    for (const Upload& u : uploads) stagingBytes += u.bytes;
    if (stagingBytes > 0) {
        GpuResources scratch(ctx);
        Buffer staging = createHostBuffer(scratch, stagingBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
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
                          kShaderReads | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        });
    }

    const VkFormat uint4 = VK_FORMAT_R32G32B32A32_UINT;
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkFormat uint1 = VK_FORMAT_R32_UINT;
    auto texels = [&](uint32_t binding, const Buffer& buffer, VkFormat format) {
        return texelBuffer(binding, compute, createTexelView(owner, buffer, format));
    };
    const DescriptorBinding bindings[] = {storageBuffer(PHYSICS_BINDING_UNIFORMS, compute, pass.uniforms),
                                          texels(PHYSICS_BINDING_PARAMS, pass.params, uint4),
                                          texels(PHYSICS_BINDING_SKELETONS, pass.skeletons, uint4),
                                          storageBuffer(PHYSICS_BINDING_STATES, compute, pass.states),
                                          storageBuffer(PHYSICS_BINDING_POSES, compute, pass.poses),
                                          texels(PHYSICS_BINDING_JOINT_SKELETON, pass.jointSkeleton, uint1),
                                          texels(PHYSICS_BINDING_JOINT_ORDER, pass.jointOrder, uint1),
                                          texels(PHYSICS_BINDING_STATE_TEXELS, pass.states, uint4),
                                          texels(PHYSICS_BINDING_POSE_TEXELS, pass.poses, uint4)};
    // 8 bytes of push constants: the physics dispatch or the pose level.
    static_assert(sizeof(gpu::PhysicsDispatch) == sizeof(glm::uvec2));
    pass.set = createComputeSet(owner, bindings, sizeof(glm::uvec2));
    for (uint32_t steps = 1; steps <= PHYSICS_MAX_DISPATCH_SUB_STEPS; ++steps) {
        const VkSpecializationMapEntry entry{PHYSICS_SUB_STEPS_CONSTANT_ID, 0, sizeof(steps)};
        const VkSpecializationInfo specialization{1, &entry, sizeof(steps), &steps};
        pass.physicsPipelines[steps - 1] =
            createComputePipeline(owner, pass.set.pipelineLayout, spirv_physics_comp, &specialization);
    }
    pass.posePipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_pose_comp);
    return pass;
}

void setPhysicsUniforms(const PhysicsPass& pass, const gpu::PhysicsUniforms& uniforms) {
    // The shaders bound their invocations by the counts of the buffers they were given.
    gpu::PhysicsUniforms u = uniforms;
    u.counts.x = pass.skeletonCount;
    u.counts.y = pass.jointCount;
    std::memcpy(pass.uniforms.mapped, &u, sizeof(u));
}

void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass, std::span<const gpu::PhysicsDispatch> dispatches,
                       GpuTimer* timer) {
    // The previous frame's vertex shaders may still read the poses the pose
    // dispatch overwrites (write-after-read: execution only), and the
    // previous physics and pose dispatches wrote the states and poses read
    // here (read-after-write: make them visible).
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  kShaderReads | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    if (pass.jointCount == 0) return;

    bindComputeSet(cmd, pass.set);
    const gpu::PhysicsDispatch poseOnly{0.0f, 0};
    if (dispatches.empty()) dispatches = {&poseOnly, 1};
    for (const gpu::PhysicsDispatch& d : dispatches)
        if (d.subSteps > PHYSICS_MAX_DISPATCH_SUB_STEPS)
            throw std::invalid_argument("a physics dispatch takes at most " +
                                        std::to_string(PHYSICS_MAX_DISPATCH_SUB_STEPS) + " sub-steps, not " +
                                        std::to_string(d.subSteps));
    if (timer) beginScopeOutsideRendering(cmd, *timer, kPhysicsScope);
    for (size_t i = 0; i < dispatches.size(); ++i) {
        if (i > 0) {
            // This dispatch reads the states and poses the one before wrote.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kShaderReads | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        recordPhysicsDispatch(cmd, pass, dispatches[i]);
        const bool last = i + 1 == dispatches.size();
        if (last && timer) {
            endScope(cmd, *timer);
            beginScopeOutsideRendering(cmd, *timer, kPoseScope);
        }
        recordPoseLevels(cmd, pass);
    }
    if (timer) endScope(cmd, *timer);
    // The vertex shaders skin plant vertices with the new poses.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void recordPhysicsPass(VkCommandBuffer cmd, const PhysicsPass& pass, GpuTimer* timer) {
    const auto* uniforms = static_cast<const gpu::PhysicsUniforms*>(pass.uniforms.mapped);
    const gpu::PhysicsDispatch dispatch{uniforms->windDetail.z, uniforms->counts.z};
    recordPhysicsPass(cmd, pass, {&dispatch, 1}, timer);
}

void readPhysicsState(const GpuContext& ctx, const PhysicsPass& pass, std::vector<gpu::JointState>& states,
                      std::vector<gpu::JointPose>& poses) {
    states.resize(pass.jointCount);
    poses.resize(pass.jointCount);
    if (pass.jointCount == 0) return;
    const VkDeviceSize stateBytes = VkDeviceSize(pass.jointCount) * sizeof(gpu::JointState);
    const VkDeviceSize poseBytes = VkDeviceSize(pass.jointCount) * sizeof(gpu::JointPose);
    GpuResources scratch(ctx);
    Buffer readback = createHostBuffer(scratch, stateBytes + poseBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
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
}

} // namespace pf
