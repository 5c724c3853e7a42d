#include "engine/field/cull_pass.h"

#include "engine/field/visible_lists.h"
#include "engine/vk/depth_pyramid.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/cluster_layouts.h"

#include "shaders/build_draws_comp.spv.h"
#include "shaders/cull_comp.spv.h"
#include "shaders/cull_late_comp.spv.h"
#include "shaders/shadow_cull_comp.spv.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace pf {

namespace {

// Buffers of zero size are invalid; an empty field still gets valid ones.
VkDeviceSize atLeastOneWord(VkDeviceSize bytes) { return std::max<VkDeviceSize>(bytes, 4); }

Buffer createDeviceBuffer(GpuResources& owner, VkDeviceSize size, VkBufferUsageFlags usage) {
    return createBuffer(owner, atLeastOneWord(size), usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

// Writes the uniforms with counts.x and counts.y (instances, templates) taken from the pass.
template <class Uniforms>
void writeCullUniforms(const CullPass& pass, Uniforms u) {
    u.counts.x = pass.instanceCount;
    u.counts.y = pass.templateCount;
    std::memcpy(pass.uniforms.mapped, &u, sizeof(u));
}

// Counters of one region: one per (model, LOD).
VkDeviceSize countersPerRegion(const CullPass& pass) { return VkDeviceSize(pass.modelCount) * LOD_COUNT; }
// Both regions and the late phase's count of occluded plants.
VkDeviceSize counterWords(const CullPass& pass) { return CULL_PHASE_REGIONS * countersPerRegion(pass) + 1; }
uint32_t regionOf(uint32_t phase) { return phase == CULL_PHASE_LATE ? 1u : 0u; }

} // namespace

CullPass createCullPass(GpuResources& owner, const CullPassInputs& inputs) {
    const GpuContext& ctx = owner.ctx();
    if (inputs.instanceCount > FIELD_MAX_INSTANCES)
        throw DeviceLimitError("field of " + std::to_string(inputs.instanceCount) + " instances exceeds " +
                               std::to_string(FIELD_MAX_INSTANCES));
    CullPass pass;
    pass.instanceCount = inputs.instanceCount;
    pass.modelCount = inputs.modelCount;
    pass.templateCount = uint32_t(inputs.templates.size());
    for (uint32_t t = 0; t < pass.templateCount; ++t) {
        const uint32_t drawClass = inputs.templates[t].mesh.w;
        if (drawClass >= DRAW_CLASS_COUNT || (t > 0 && drawClass < inputs.templates[t - 1].mesh.w))
            throw std::runtime_error("draw templates must be sorted by draw class");
        if (pass.templatesPerClass[drawClass]++ == 0) pass.firstTemplateOfClass[drawClass] = t;
    }

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkBufferUsageFlags indirect = storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    if (inputs.near) {
        pass.near = inputs.near->buffer;
    } else {
        const std::vector<uint32_t> chunks =
            allPlantChunks(pass.instanceCount, ctx.properties.limits.maxComputeWorkGroupCount[0]);
        pass.allPlants = createDeviceBufferWithData(owner, chunks.data(), chunks.size() * 4, indirect);
        pass.near = pass.allPlants.buffer;
    }
    const bool camera = inputs.kind == CullKind::Camera;
    pass.uniforms = createHostBuffer(owner, camera ? sizeof(gpu::CullUniforms) : sizeof(gpu::ShadowCullUniforms),
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (pass.templateCount > 0)
        pass.templates =
            createDeviceBufferWithData(owner, inputs.templates.data(), inputs.templates.size_bytes(), storage);
    else
        pass.templates = createDeviceBuffer(owner, 0, storage);
    pass.state = createDeviceBuffer(owner, camera ? VkDeviceSize(pass.instanceCount) * 4 : 0,
                                    storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    pass.counts = createDeviceBuffer(owner, counterWords(pass) * 4, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    // Written here, read by the draw shaders through a texel view.
    pass.visible = createDeviceBuffer(owner, VkDeviceSize(pass.instanceCount) * LOD_COUNT * 4,
                                      storage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    const VkDeviceSize regions = CULL_PHASE_REGIONS;
    pass.commands =
        createDeviceBuffer(owner, regions * DRAW_CLASS_COUNT * pass.templateCount * sizeof(gpu::DrawCommand), indirect);
    pass.drawCounts =
        createDeviceBuffer(owner, regions * DRAW_CLASS_COUNT * 4, indirect | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    pass.allCommands = createDeviceBuffer(owner, regions * pass.templateCount * sizeof(gpu::DrawCommand), indirect);
    pass.readback = createHostBuffer(owner, (counterWords(pass) + regions * DRAW_CLASS_COUNT) * 4,
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    // Until a first frame resets it, every plant is settled at LOD 0.
    if (camera)
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, pass.state.buffer, 0, VK_WHOLE_SIZE, LOD_STATE_SETTLED << 8);
            // Waiting for the queue is no memory dependency: the first cull reads it.
            transferToComputeBarrier(cmd);
        });

    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    const DescriptorBinding bindings[] = {
        storageBuffer(CULL_BINDING_UNIFORMS, compute, pass.uniforms),
        storageBuffer(CULL_BINDING_INSTANCES, compute, *inputs.instances),
        storageBuffer(CULL_BINDING_MODELS, compute, *inputs.models),
        storageBuffer(CULL_BINDING_STATE, compute, pass.state),
        storageBuffer(CULL_BINDING_COUNTS, compute, pass.counts),
        storageBuffer(CULL_BINDING_VISIBLE, compute, pass.visible),
        storageBuffer(CULL_BINDING_TEMPLATES, compute, pass.templates),
        storageBuffer(CULL_BINDING_COMMANDS, compute, pass.commands),
        storageBuffer(CULL_BINDING_DRAW_COUNTS, compute, pass.drawCounts),
        storageBuffer(CULL_BINDING_ALL_COMMANDS, compute, pass.allCommands),
        storageBuffer(CULL_BINDING_NEAR, compute, inputs.near ? *inputs.near : pass.allPlants)};
    const VkDescriptorSetLayout pyramid = createDepthPyramidReadLayout(owner);
    static_assert(CULL_SET_PYRAMID == 1, "the pyramid's set follows the pass's own");
    pass.set = createComputeSet(owner, bindings, sizeof(gpu::CullPush),
                                camera ? std::span<const VkDescriptorSetLayout>(&pyramid, 1)
                                       : std::span<const VkDescriptorSetLayout>());
    const std::span<const uint32_t> cullShader =
        camera ? std::span<const uint32_t>(spirv_cull_comp) : std::span<const uint32_t>(spirv_shadow_cull_comp);
    pass.cullPipeline = createComputePipeline(owner, pass.set.pipelineLayout, cullShader);
    if (camera) pass.latePipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_cull_late_comp);
    pass.buildDrawsPipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_build_draws_comp);
    return pass;
}

void setCullUniforms(const CullPass& pass, const gpu::CullUniforms& uniforms) { writeCullUniforms(pass, uniforms); }

void setCullUniforms(const CullPass& pass, const gpu::ShadowCullUniforms& uniforms) {
    writeCullUniforms(pass, uniforms);
}

void recordCullPass(VkCommandBuffer cmd, const CullPass& pass, uint32_t phase, VkDescriptorSet pyramid) {
    // The previous frame (or this frame's early phase) may still draw from
    // commands and visible and copy counts (write-after-read: execution
    // only), and the previous cull wrote the state and counts this cull
    // reads (read-after-write: make them visible).
    previousFrameReadsBarrier(cmd);

    // The late phase counts on from the early phase's counters and appends
    // after its entries: only the first phase of a frame clears them.
    if (phase != CULL_PHASE_LATE) {
        vkCmdFillBuffer(cmd, pass.counts.buffer, 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, pass.drawCounts.buffer, 0, VK_WHOLE_SIZE, 0);
        // Both shaders increment the zeroed counters with atomics. (Fills are
        // transfer-stage work; layers disagree on CLEAR vs COPY, TRANSFER is both.)
        transferToComputeBarrier(cmd);
    }

    const gpu::CullPush push{glm::uvec4(phase, uint32_t(countersPerRegion(pass)), 0u, 0u)};
    vkCmdPushConstants(cmd, pass.set.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                      phase == CULL_PHASE_LATE ? pass.latePipeline : pass.cullPipeline);
    bindComputeSet(cmd, pass.set);
    if (phase == CULL_PHASE_LATE)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.set.pipelineLayout, CULL_SET_PYRAMID, 1,
                                &pyramid, 0, nullptr);
    vkCmdDispatchIndirect(cmd, pass.near, NEAR_CHUNK_DISPATCH_OFFSET);
    // build_draws reads the final per-list counts.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.buildDrawsPipeline);
    vkCmdDispatch(cmd, (pass.templateCount + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE, 1, 1);
    // Indirect draws read commands and drawCounts, vertex shaders the visible
    // lists (written by cull, covered as an earlier compute write), and the
    // copy below the counters.
    memoryBarrier(
        cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
        VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);

    // Every phase copies all counters: the frame's last phase leaves them final.
    const VkBufferCopy countsRegion{0, 0, counterWords(pass) * 4};
    vkCmdCopyBuffer(cmd, pass.counts.buffer, pass.readback.buffer, 1, &countsRegion);
    const VkBufferCopy drawCountsRegion{0, countsRegion.size, CULL_PHASE_REGIONS * DRAW_CLASS_COUNT * 4};
    vkCmdCopyBuffer(cmd, pass.drawCounts.buffer, pass.readback.buffer, 1, &drawCountsRegion);
    // The host reads the counters after the frame's fence.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
}

void drawClassIndirect(VkCommandBuffer cmd, const GpuContext& ctx, const CullPass& pass, uint32_t drawClass,
                       uint32_t phase) {
    const uint32_t stride = sizeof(gpu::DrawCommand);
    const VkDeviceSize region = regionOf(phase);
    if (ctx.drawIndirectCount) {
        const VkDeviceSize list = region * DRAW_CLASS_COUNT + drawClass;
        vkCmdDrawIndexedIndirectCount(cmd, pass.commands.buffer, list * pass.templateCount * stride,
                                      pass.drawCounts.buffer, list * 4, pass.templateCount, stride);
        return;
    }
    const uint32_t count = pass.templatesPerClass[drawClass];
    const VkDeviceSize first = (region * pass.templateCount + pass.firstTemplateOfClass[drawClass]) * stride;
    if (count == 0) return;
    if (ctx.multiDrawIndirect) {
        vkCmdDrawIndexedIndirect(cmd, pass.allCommands.buffer, first, count, stride);
        return;
    }
    for (uint32_t i = 0; i < count; ++i)
        vkCmdDrawIndexedIndirect(cmd, pass.allCommands.buffer, first + VkDeviceSize(i) * stride, 1, stride);
}

CullCounts readCullCounts(const CullPass& pass) {
    const auto* words = static_cast<const uint32_t*>(pass.readback.mapped);
    const size_t perRegion = countersPerRegion(pass);
    const uint32_t* drawCounts = words + counterWords(pass);
    CullCounts out;
    out.perModelLod.assign(words, words + perRegion);
    for (size_t i = 0; i < perRegion; ++i) out.perModelLod[i] += words[perRegion + i];
    out.occluded = words[CULL_PHASE_REGIONS * perRegion];
    for (uint32_t c = 0; c < DRAW_CLASS_COUNT; ++c)
        out.drawsPerClass[c] = drawCounts[c] + drawCounts[DRAW_CLASS_COUNT + c];
    for (size_t i = 0; i < out.perModelLod.size(); ++i) out.perLod[i % LOD_COUNT] += out.perModelLod[i];
    return out;
}

} // namespace pf
