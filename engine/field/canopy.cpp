#include "engine/field/canopy.h"

#include "engine/vk/compute_set.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/canopy_mesh.h"

#include "shaders/canopy_reduce_comp.spv.h"
#include "shaders/canopy_resolve_comp.spv.h"
#include "shaders/canopy_splat_comp.spv.h"

#include <algorithm>

namespace pf {
namespace {

// A dispatch of `groups` workgroups in rows of at most maxComputeWorkGroupCount[0].
void dispatchRows(VkCommandBuffer cmd, const GpuContext& ctx, uint32_t groups) {
    const uint32_t row = std::min(groups, ctx.properties.limits.maxComputeWorkGroupCount[0]);
    if (row > 0) vkCmdDispatch(cmd, row, (groups + row - 1) / row, 1);
}

void pushBake(VkCommandBuffer cmd, const ComputeSet& set, const gpu::CanopyBakePush& push) {
    vkCmdPushConstants(cmd, set.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
}

// Each pass reads what the one before wrote.
void computeToCompute(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

} // namespace

std::vector<float> canopyGround(const ClusterTree& tree, const Heightfield& ground) {
    std::vector<float> heights;
    heights.reserve(tree.nodes.size() * CANOPY_CELLS);
    for (const gpu::ClusterNode& node : tree.nodes)
        for (uint32_t j = 0; j < CLUSTER_GRID; ++j)
            for (uint32_t i = 0; i < CLUSTER_GRID; ++i)
                heights.push_back(heightAt(ground, node.square.x + (float(i) + 0.5f) * node.square.w,
                                           node.square.y + (float(j) + 0.5f) * node.square.w));
    return heights;
}

Buffer bakeCanopy(GpuResources& owner, const CanopyBakeInputs& in) {
    const GpuContext& ctx = owner.ctx();
    const ClusterTree& tree = *in.tree;
    const uint32_t nodeCells = uint32_t(tree.nodes.size()) * CANOPY_CELLS;
    GpuResources scratch(ctx); // what only the bake needs
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const Buffer cells = createBuffer(scratch, VkDeviceSize(nodeCells) * CANOPY_BAKE_WORDS * 4,
                                      storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    const std::vector<float> groundHeights = canopyGround(tree, *in.ground);
    const Buffer ground =
        createDeviceBufferWithData(scratch, groundHeights.data(), groundHeights.size() * sizeof(float), storage);
    Buffer canopy =
        createBuffer(owner, VkDeviceSize(nodeCells) * sizeof(gpu::CanopyCell),
                     storage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    const DescriptorBinding bindings[] = {
        storageBuffer(CANOPY_BAKE_BINDING_NODES, compute, *in.nodes),
        storageBuffer(CANOPY_BAKE_BINDING_INSTANCES, compute, *in.instances),
        storageBuffer(CANOPY_BAKE_BINDING_MODELS, compute, *in.models),
        sampledImage(CANOPY_BAKE_BINDING_ATLAS, compute, in.atlas->sampler, in.atlas->color.view),
        storageBuffer(CANOPY_BAKE_BINDING_CELLS, compute, cells),
        storageBuffer(CANOPY_BAKE_BINDING_GROUND, compute, ground),
        storageBuffer(CANOPY_BAKE_BINDING_CANOPY, compute, canopy)};
    const ComputeSet set = createComputeSet(scratch, bindings, sizeof(gpu::CanopyBakePush));
    const VkPipeline splat = createComputePipeline(scratch, set.pipelineLayout, spirv_canopy_splat_comp);
    const VkPipeline reduce = createComputePipeline(scratch, set.pipelineLayout, spirv_canopy_reduce_comp);
    const VkPipeline resolve = createComputePipeline(scratch, set.pipelineLayout, spirv_canopy_resolve_comp);

    const glm::vec4 params(in.thresholdPixels, in.crownRadius, 0.0f, 0.0f);
    const uint32_t frames = in.atlas->settings.frames;
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, cells.buffer, 0, VK_WHOLE_SIZE, 0);
        // The splat adds into the zeroed cells with atomics.
        transferToComputeBarrier(cmd);
        bindComputeSet(cmd, set);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, splat);
        pushBake(cmd, set, {glm::uvec4(0, tree.leafCount(), frames, 0), params});
        dispatchRows(cmd, ctx, tree.leafCount());
        // Each level from the one below it.
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, reduce);
        for (uint32_t level = 1; level < tree.levels(); ++level) {
            computeToCompute(cmd);
            const uint32_t first = tree.levelStart[level], count = tree.levelStart[level + 1] - first;
            pushBake(cmd, set, {glm::uvec4(first, count, frames, 0), params});
            dispatchRows(cmd, ctx, (count * CANOPY_CELLS + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE);
        }
        computeToCompute(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolve);
        pushBake(cmd, set, {glm::uvec4(0, tree.nodes.size(), frames, 0), params});
        dispatchRows(cmd, ctx, (nodeCells + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE);
        // Waiting for the queue is no memory dependency: the canopy's vertex shader reads the cells.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    return canopy;
}

std::vector<uint32_t> canopyMeshIndices() {
    std::vector<uint32_t> indices;
    const uint32_t side = CANOPY_GRID_SIDE;
    for (uint32_t z = 0; z + 1 < side; ++z)
        for (uint32_t x = 0; x + 1 < side; ++x) {
            const uint32_t corner = z * side + x;
            indices.insert(indices.end(),
                           {corner, corner + side, corner + 1, corner + 1, corner + side, corner + side + 1});
        }
    for (uint32_t k = 0; k < CANOPY_RING_VERTICES; ++k) {
        const uint32_t next = (k + 1) % CANOPY_RING_VERTICES;
        const uint32_t top = gpu::canopyGridVertex(gpu::canopyRingVertex(k));
        const uint32_t topNext = gpu::canopyGridVertex(gpu::canopyRingVertex(next));
        const uint32_t bottom = CANOPY_GRID_VERTICES + k, bottomNext = CANOPY_GRID_VERTICES + next;
        indices.insert(indices.end(), {top, topNext, bottomNext, top, bottomNext, bottom});
    }
    return indices;
}

} // namespace pf
