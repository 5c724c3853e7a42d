#include "engine/field/cluster_pass.h"

#include "engine/vk/pipeline.h"
#include "shaders/shared/cluster_layouts.h"

#include "shaders/cluster_comp.spv.h"
#include "shaders/near_dispatch_comp.spv.h"

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

namespace pf {

ClusterPass createClusterPass(GpuResources& owner, const ClusterTree& tree, const Buffer& nodes,
                              const gpu::DrawCommand& farMesh) {
    const GpuContext& ctx = owner.ctx();
    ClusterPass pass;
    pass.nodeCount = uint32_t(tree.nodes.size());
    pass.leafCount = tree.leafCount();
    pass.farMesh = farMesh;
    pass.farMesh.instanceCount = 0;
    pass.maxGroupsPerRow = ctx.properties.limits.maxComputeWorkGroupCount[0];
    if (pass.nodeCount == 0) throw std::runtime_error("cluster pass: the tree has no node");
    if (pass.nodeCount > ctx.properties.limits.maxComputeWorkGroupCount[0] * uint64_t(CULL_GROUP_SIZE))
        throw std::runtime_error("cluster pass: " + std::to_string(pass.nodeCount) + " nodes are too many to dispatch");
    uint64_t chunks = 0;
    for (uint32_t l = 0; l < pass.leafCount; ++l)
        chunks += (tree.nodes[l].range.y + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE;

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const VkBufferUsageFlags cleared = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    auto device = [&](VkDeviceSize bytes, VkBufferUsageFlags usage) {
        return createBuffer(owner, bytes, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    };
    pass.uniforms = createHostBuffer(owner, sizeof(gpu::ClusterUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pass.leafState = device(VkDeviceSize(pass.leafCount) * 4, cleared);
    pass.near = device(NEAR_CHUNK_HEADER_BYTES + chunks * 8, cleared | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    // The canopy's vertex shader reads the far list through a texel view.
    pass.far = device(VkDeviceSize(pass.nodeCount) * 4, storage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    pass.farDraw = device(sizeof(gpu::DrawCommand), cleared | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    pass.stats = device(CLUSTER_STAT_COUNT * 4, cleared);
    pass.readback = createHostBuffer(owner, CLUSTER_STAT_COUNT * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    // No leaf was near before the first frame.
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, pass.leafState.buffer, 0, VK_WHOLE_SIZE, 0);
        // Waiting for the queue is no memory dependency: the first cluster pass reads it.
        transferToComputeBarrier(cmd);
    });

    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    const DescriptorBinding bindings[] = {storageBuffer(CLUSTER_BINDING_UNIFORMS, compute, pass.uniforms),
                                          storageBuffer(CLUSTER_BINDING_NODES, compute, nodes),
                                          storageBuffer(CLUSTER_BINDING_LEAF_STATE, compute, pass.leafState),
                                          storageBuffer(CLUSTER_BINDING_NEAR, compute, pass.near),
                                          storageBuffer(CLUSTER_BINDING_FAR, compute, pass.far),
                                          storageBuffer(CLUSTER_BINDING_FAR_DRAW, compute, pass.farDraw),
                                          storageBuffer(CLUSTER_BINDING_STATS, compute, pass.stats)};
    pass.set = createComputeSet(owner, bindings);
    pass.clusterPipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_cluster_comp);
    pass.dispatchPipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_near_dispatch_comp);
    return pass;
}

void setClusterUniforms(const ClusterPass& pass, gpu::ClusterUniforms uniforms) {
    uniforms.counts.x = pass.nodeCount;
    uniforms.counts.y = pass.leafCount;
    uniforms.limits = glm::uvec4(pass.maxGroupsPerRow, 0, 0, 0);
    std::memcpy(pass.uniforms.mapped, &uniforms, sizeof(uniforms));
}

void recordClusterPass(VkCommandBuffer cmd, const ClusterPass& pass) {
    // The previous frame may still cull from the chunks, draw from the far
    // list and copy the counters (write-after-read: execution only); its
    // cluster pass wrote the leaf state this one reads.
    previousFrameReadsBarrier(cmd);
    vkCmdFillBuffer(cmd, pass.near.buffer, 0, 4, 0);
    vkCmdFillBuffer(cmd, pass.stats.buffer, 0, VK_WHOLE_SIZE, 0);
    vkCmdUpdateBuffer(cmd, pass.farDraw.buffer, 0, sizeof(pass.farMesh), &pass.farMesh);
    // The shader appends with atomics on the zeroed counters.
    transferToComputeBarrier(cmd);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.clusterPipeline);
    bindComputeSet(cmd, pass.set);
    vkCmdDispatch(cmd, (pass.nodeCount + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE, 1, 1);
    // near_dispatch reads the final chunk count.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.dispatchPipeline);
    vkCmdDispatch(cmd, 1, 1, 1);
    // The cull dispatches indirectly over the chunks and reads them, the
    // canopy draws indirectly from the far list, the copy reads the counters.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                  VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);
    const VkBufferCopy region{0, 0, CLUSTER_STAT_COUNT * 4};
    vkCmdCopyBuffer(cmd, pass.stats.buffer, pass.readback.buffer, 1, &region);
    // The host reads the counters after the frame's fence.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
}

void drawCanopyIndirect(VkCommandBuffer cmd, const GpuContext& ctx, const ClusterPass& pass) {
    if (!ctx.drawIndirectCount) {
        vkCmdDrawIndexedIndirect(cmd, pass.farDraw.buffer, 0, 1, sizeof(gpu::DrawCommand));
        return;
    }
    // The command's instance count is its draw count, at most one: lavapipe
    // (Mesa 22.3) draws nothing from a plain vkCmdDrawIndexedIndirect of a
    // command the GPU wrote, but does from the counted form.
    vkCmdDrawIndexedIndirectCount(cmd, pass.farDraw.buffer, 0, pass.farDraw.buffer,
                                  offsetof(gpu::DrawCommand, instanceCount), 1, sizeof(gpu::DrawCommand));
}

std::array<uint32_t, CLUSTER_STAT_COUNT> readClusterStats(const ClusterPass& pass) {
    std::array<uint32_t, CLUSTER_STAT_COUNT> stats{};
    std::memcpy(stats.data(), pass.readback.mapped, sizeof(stats));
    return stats;
}

} // namespace pf
