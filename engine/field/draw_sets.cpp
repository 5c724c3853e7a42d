#include "engine/field/draw_sets.h"

namespace pf {
namespace {

constexpr VkFormat kUint4 = VK_FORMAT_R32G32B32A32_UINT;
constexpr VkFormat kUint1 = VK_FORMAT_R32_UINT;

DescriptorBinding texels(GpuResources& owner, uint32_t binding, const Buffer& buffer, VkFormat format) {
    return texelBuffer(binding, kDrawStages, createTexelView(owner, buffer, format));
}

} // namespace

DrawTable createDrawTable(GpuResources& owner, const DrawTableInputs& in) {
    const FieldGeometry& g = *in.geometry;
    // Without clusters the canopy is never drawn; its bindings get one texel.
    const Buffer placeholder = in.clusters ? Buffer{}
                                           : createBuffer(owner, 16, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    DrawTable table;
    table.bindings = {
        uniformBuffer(FIELD_BINDING_FRAME, kDrawStages, *in.frame),
        texels(owner, FIELD_BINDING_INSTANCES, in.plants->instances, kUint4),
        texelBuffer(FIELD_BINDING_VISIBLE, kDrawStages, VK_NULL_HANDLE),
        texels(owner, FIELD_BINDING_VERTICES, g.vertices, kUint4),
        texels(owner, FIELD_BINDING_MODELS, in.plants->models, kUint4),
        sampledImage(FIELD_BINDING_ATLAS_COLOR, kDrawStages, g.atlas.sampler, g.atlas.color.view),
        sampledImage(FIELD_BINDING_ATLAS_NORMAL, kDrawStages, g.atlas.sampler, g.atlas.normalDepth.view),
        sampledImage(FIELD_BINDING_IMPOSTOR_SHADOW, kDrawStages, g.atlas.sampler, g.atlas.shadow.view),
        sampledImage(FIELD_BINDING_SHADOW, kDrawStages, in.shadow->sampler, in.shadow->depth.view),
        texels(owner, FIELD_BINDING_TERRAIN, g.terrainVertices, kUint4),
        texels(owner, FIELD_BINDING_SKELETONS, in.motion->pass.skeletons, kUint4),
        texels(owner, FIELD_BINDING_POSES, in.motion->pass.poses, kUint4),
        texels(owner, FIELD_BINDING_INSTANCE_SKELETON, in.motion->instanceSkeleton, kUint1),
        texels(owner, FIELD_BINDING_IMPOSTOR_OUTLINES, g.outlines, kUint4),
        texels(owner, FIELD_BINDING_CLUSTER_NODES, in.clusters ? in.clusters->nodes : placeholder, kUint4),
        texels(owner, FIELD_BINDING_CANOPY, in.clusters ? in.clusters->canopy : placeholder, kUint4),
        texels(owner, FIELD_BINDING_CANOPY_FAR, in.clusters ? in.cameraClusters->far : placeholder, kUint1),
        raytracedSunBinding(*in.raytracedSun, kDrawStages)};
    table.setLayout = createSetLayout(owner, table.bindings);
    table.layout = createPipelineLayout(owner, table.setLayout, {kDrawStages, 0, sizeof(gpu::FieldPush)});
    return table;
}

std::vector<VkDescriptorSet> createDrawSets(GpuResources& owner, const DrawTable& table,
                                            std::span<const Buffer* const> visibleLists) {
    std::vector<std::vector<DescriptorBinding>> bindings;
    for (const Buffer* visible : visibleLists) {
        bindings.push_back(table.bindings);
        for (DescriptorBinding& b : bindings.back())
            if (b.binding == FIELD_BINDING_VISIBLE) b = texels(owner, FIELD_BINDING_VISIBLE, *visible, kUint1);
    }
    const std::vector<DescriptorTable> tables(bindings.begin(), bindings.end());
    return createSets(owner, table.setLayout, tables);
}

void writeRaytracedSunVisibility(const GpuContext& ctx, std::span<const VkDescriptorSet> sets,
                                 const RaytracedSunPass& raytracedSun) {
    // A write names no stages: the sets' layout keeps the colour pass's.
    const DescriptorBinding visibility = raytracedSunBinding(raytracedSun, VK_SHADER_STAGE_FRAGMENT_BIT);
    for (VkDescriptorSet set : sets) writeSet(ctx.device, set, {&visibility, 1});
}

void bindDrawSet(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
}

void pushFieldPass(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t pass, uint32_t impostorPart) {
    const gpu::FieldPush push{pass, impostorPart};
    vkCmdPushConstants(cmd, layout, kDrawStages, 0, sizeof(push), &push);
}

} // namespace pf
