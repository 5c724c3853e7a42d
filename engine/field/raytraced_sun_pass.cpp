#include "engine/field/raytraced_sun_pass.h"

#include "engine/raytrace/field_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "shaders/shared/field_layouts.h"
#include "shaders/shared/raytraced_sun_layouts.h"

#include "shaders/raytraced_sun_comp.spv.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// The trace's table: the graph, then the frame's two images.
std::vector<DescriptorBinding> traceTable(const RaytracedSunPass& pass) {
    std::vector<DescriptorBinding> table = graphBindings(pass.graph, kCompute);
    table.push_back(storageImage(RAYTRACED_SUN_BINDING_ORIGINS, kCompute, pass.images.origins.view));
    table.push_back(storageImage(RAYTRACED_SUN_BINDING_VISIBILITY, kCompute, pass.images.visibility.view));
    return table;
}

// Images of `extent`, their visibility 1 everywhere until a trace writes
// it, in the layout the colour pass samples.
RaytracedSunImages createRaytracedSunImages(const GpuContext& ctx, VkExtent2D extent) {
    RaytracedSunImages images;
    images.resources = std::make_unique<GpuResources>(ctx);
    images.extent = extent;
    images.origins = createImage(*images.resources, {extent, kRaytracedOriginFormat,
                                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT});
    images.depth =
        createImage(*images.resources, {extent, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                        VK_IMAGE_ASPECT_DEPTH_BIT});
    images.visibility = createImage(
        *images.resources, {extent, VK_FORMAT_R32_SFLOAT,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    VkClearValue lit{};
    lit.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    clearForSampling(ctx, images.visibility, VK_IMAGE_ASPECT_COLOR_BIT, lit);
    return images;
}

} // namespace

RaytracedSunPass createRaytracedSunPlaceholder(GpuResources& owner) {
    RaytracedSunPass pass;
    VkSamplerCreateInfo nearest{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    nearest.addressModeU = nearest.addressModeV = nearest.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    pass.sampler = createSampler(owner, nearest);
    pass.images = createRaytracedSunImages(owner.ctx(), {1, 1});
    return pass;
}

RaytracedSunPass createRaytracedSunPass(GpuResources& owner, const FieldContent& content,
                                        std::span<const gpu::FieldInstance> plants, const lsys::MemoryBudget& memory) {
    // A ray from anywhere on the field reaches past every plant within the
    // diagonal of the terrain and the height of the tallest crown.
    float top = 0.0f;
    for (const PlantModelInfo& model : content.models.models) top = std::max(top, model.gpu.boxMax.y);
    float highest = 0.0f;
    for (const PlantInstance& plant : content.plants) highest = std::max(highest, plant.scale);
    const float reach = std::sqrt(2.0f) * content.terrain.size + top * highest + 1000.0f;
    lsys::need(memory, "the field's graph for ray-traced shadows",
               fieldGraphBytes(content.models, content.plants.size()));
    RaytracedSunPass pass = createRaytracedSunPlaceholder(owner);
    pass.graph = uploadGraph(owner, packFieldGraph(content.models, plants));
    pass.rayLength = reach;
    pass.set = createComputeSet(owner, traceTable(pass), sizeof(gpu::RaytracedSunPush));
    pass.pipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_raytraced_sun_comp);
    return pass;
}

DescriptorBinding raytracedSunBinding(const RaytracedSunPass& pass, VkShaderStageFlags stages) {
    return sampledImage(FIELD_BINDING_RAYTRACED_SUN, stages, pass.sampler, pass.images.visibility.view);
}

bool resizeRaytracedSunImages(const GpuContext& ctx, RaytracedSunPass& pass, VkExtent2D extent) {
    if (pass.images.extent.width == extent.width && pass.images.extent.height == extent.height) return false;
    pass.images = createRaytracedSunImages(ctx, extent);
    writeSet(ctx.device, pass.set.descriptorSet, traceTable(pass));
    return true;
}

void beginRaytracedOrigins(VkCommandBuffer cmd, const RaytracedSunImages& images) {
    // The last frame's trace read the origins; this pass overwrites them (and its depth).
    imageBarrier(cmd, images.origins.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    discardDepthAttachment(cmd, images.depth.image);
    VkRenderingAttachmentInfo origins{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    origins.imageView = images.origins.view;
    origins.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    origins.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR; // w 0: no ray where nothing is drawn
    origins.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    const VkRenderingAttachmentInfo depth = clearedDepthAttachment(images.depth.view, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    // As the colour pass: a pixel's origin is at its own pixel.
    beginFlippedRendering(cmd, images.extent, origins, depth);
}

void endRaytracedOrigins(VkCommandBuffer cmd, const RaytracedSunImages& images) {
    vkCmdEndRendering(cmd);
    imageBarrier(cmd, images.origins.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL});
}

void recordRaytracedSun(VkCommandBuffer cmd, const RaytracedSunPass& pass, const glm::vec3& sun) {
    const RaytracedSunImages& images = pass.images;
    // The last frame's colour pass sampled the visibility; the trace overwrites every pixel.
    imageBarrier(cmd, images.visibility.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline);
    bindComputeSet(cmd, pass.set);
    const gpu::RaytracedSunPush push{glm::vec4(sun, pass.rayLength),
                                     glm::uvec4(images.extent.width, images.extent.height, pass.graph.rootNode, 0u)};
    vkCmdPushConstants(cmd, pass.set.pipelineLayout, kCompute, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, (images.extent.width + RAYTRACED_SUN_GROUP_SIZE - 1) / RAYTRACED_SUN_GROUP_SIZE,
                  (images.extent.height + RAYTRACED_SUN_GROUP_SIZE - 1) / RAYTRACED_SUN_GROUP_SIZE, 1);
    imageBarrier(cmd, images.visibility.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
}

} // namespace pf
