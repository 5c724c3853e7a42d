#include "engine/vk/render_target.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pf {

Antialiasing supportedAntialiasing(const GpuContext& ctx, Antialiasing wanted) {
    const VkSampleCountFlags counts =
        ctx.properties.limits.framebufferColorSampleCounts & ctx.properties.limits.framebufferDepthSampleCounts;
    uint32_t samples = wanted.msaaSamples;
    while (samples > 1 && !(counts & samples)) samples >>= 1;
    wanted.msaaSamples = std::max(samples, 1u);
    return wanted;
}

RenderTarget createRenderTarget(const GpuContext& ctx, VkExtent2D extent, Antialiasing antialiasing) {
    const uint32_t maxSize = ctx.properties.limits.maxImageDimension2D;
    if (extent.width == 0 || extent.height == 0 || extent.width > maxSize || extent.height > maxSize)
        throw DeviceLimitError("image size " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                               " is outside what the device supports (1 to " + std::to_string(maxSize) + " per side)");
    RenderTarget target;
    target.resources = GpuResources(ctx);
    target.extent = extent;
    target.antialiasing = supportedAntialiasing(ctx, antialiasing);
    target.samples = VkSampleCountFlagBits(colorPassSamples(target.antialiasing));
    // Not transient: a colour pass drawn in two parts (occlusion culling)
    // stores it between them.
    if (target.samples != VK_SAMPLE_COUNT_1_BIT)
        target.msaaColor = createImage(target.resources, {.extent = extent,
                                                          .format = kColorFormat,
                                                          .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                                          .samples = target.samples});
    // The FXAA pass reads and writes these images' bytes through views of
    // another format (fxaa_pass.h).
    const bool fxaa = target.antialiasing.method == AntialiasMethod::fxaa;
    const VkImageCreateFlags fxaaViews = fxaa ? VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT : 0;
    if (fxaa)
        target.fxaaInput =
            createImage(target.resources, {.extent = extent,
                                           .format = kColorFormat,
                                           .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                           .flags = fxaaViews});
    // The window's blit samples the finished frame, also through a view of
    // another format (engine/window/window_blit.h).
    target.color = createImage(target.resources, {.extent = extent,
                                                  .format = kColorFormat,
                                                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                                  .flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT});
    if (fxaa) target.fxaa = createFxaaPass(target.resources, target.fxaaInput, target.color);
    target.depth = createImage(target.resources,
                               {.extent = extent,
                                .format = kDepthFormat,
                                .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                .aspect = VK_IMAGE_ASPECT_DEPTH_BIT,
                                .samples = target.samples});
    target.pyramid = createDepthPyramid(target.resources, target.depth);
    return target;
}

void destroyRenderTarget(RenderTarget& target) {
    target.resources.destroy();
    target = {};
}

const Image& drawnColor(const RenderTarget& target) {
    if (target.samples != VK_SAMPLE_COUNT_1_BIT) return target.msaaColor;
    if (target.antialiasing.method == AntialiasMethod::fxaa) return target.fxaaInput;
    return target.color;
}

} // namespace pf
