#include "engine/field/shadow_map.h"

#include "engine/vk/target_pass.h"

namespace pf {
namespace {

constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags2 kDepthAccess =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

// Depth-only rendering into `image` (size² texels, DEPTH_ATTACHMENT_OPTIMAL),
// cleared to 1 or keeping what it holds.
void beginDepthRendering(VkCommandBuffer cmd, const Image& image, uint32_t size, VkAttachmentLoadOp load) {
    VkRenderingAttachmentInfo depth = clearedDepthAttachment(image.view, VK_ATTACHMENT_STORE_OP_STORE);
    depth.loadOp = load;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {size, size}};
    rendering.layerCount = 1;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);

    const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {size, size}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

} // namespace

ShadowMap createShadowMap(GpuResources& owner, uint32_t size, uint32_t cacheMargin) {
    ShadowMap map;
    map.size = size;
    map.cacheSize = size + 2 * cacheMargin;
    map.depth = createImage(owner, {.extent = {size, size},
                                    .format = kShadowFormat,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                             VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    .aspect = VK_IMAGE_ASPECT_DEPTH_BIT});
    map.cache =
        createImage(owner, {.extent = {map.cacheSize, map.cacheSize},
                            .format = kShadowFormat,
                            .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            .aspect = VK_IMAGE_ASPECT_DEPTH_BIT});
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE; // outside the map: lit
    info.compareEnable = VK_TRUE;
    info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    info.maxLod = 0.0f;
    map.sampler = createSampler(owner, info);

    // Sampled before the first shadow pass (e.g. a frame with shadows off):
    // start in the layout the shaders read, cleared to "lit". The cache needs
    // nothing: it is drawn before the first copy out of it.
    VkClearValue far{};
    far.depthStencil = {1.0f, 0};
    clearForSampling(owner.ctx(), map.depth, VK_IMAGE_ASPECT_DEPTH_BIT, far);
    return map;
}

void beginShadowPass(VkCommandBuffer cmd, const ShadowMap& map) {
    // The previous frame's fragment shaders read the map; this pass overwrites it.
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, kDepthStages, kDepthAccess, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    beginDepthRendering(cmd, map.depth, map.size, VK_ATTACHMENT_LOAD_OP_CLEAR);
}

void beginShadowCachePass(VkCommandBuffer cmd, const ShadowMap& map) {
    // Earlier frames copied out of the cache; this pass overwrites it.
    imageBarrier(cmd, map.cache.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_COPY_BIT, 0, kDepthStages, kDepthAccess, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    beginDepthRendering(cmd, map.cache, map.cacheSize, VK_ATTACHMENT_LOAD_OP_CLEAR);
}

void beginShadowPassFromCache(VkCommandBuffer cmd, const ShadowMap& map, glm::ivec2 offset) {
    // The previous frame's fragment shaders read the map; the copy overwrites it.
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL});
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.srcOffset = {offset.x, offset.y, 0};
    region.dstSubresource = region.srcSubresource;
    region.extent = {map.size, map.size, 1};
    vkCmdCopyImage(cmd, map.cache.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, map.depth.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    // The frame's casters are depth-tested against the copied depth and written over it.
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, kDepthStages, kDepthAccess,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    beginDepthRendering(cmd, map.depth, map.size, VK_ATTACHMENT_LOAD_OP_LOAD);
}

void endShadowCachePass(VkCommandBuffer cmd, const ShadowMap& map) {
    vkCmdEndRendering(cmd);
    // This frame's copy, and those of the frames after it, read what the pass wrote.
    imageBarrier(cmd, map.cache.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
}

void endShadowPass(VkCommandBuffer cmd, const ShadowMap& map) {
    vkCmdEndRendering(cmd);
    // The colour pass samples the depth this pass wrote.
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
}

} // namespace pf
