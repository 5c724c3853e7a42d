#include "engine/vk/render_target.h"

#include <stdexcept>
#include <string>

namespace pf {
namespace {

VkSampleCountFlagBits supportedSamples(const GpuContext& ctx, VkSampleCountFlagBits wanted) {
    const VkSampleCountFlags counts =
        ctx.properties.limits.framebufferColorSampleCounts & ctx.properties.limits.framebufferDepthSampleCounts;
    for (uint32_t s = wanted; s > 1; s >>= 1)
        if (counts & s) return VkSampleCountFlagBits(s);
    return VK_SAMPLE_COUNT_1_BIT;
}

} // namespace

RenderTarget createRenderTarget(const GpuContext& ctx, VkExtent2D extent, VkSampleCountFlagBits samples) {
    const uint32_t maxSize = ctx.properties.limits.maxImageDimension2D;
    if (extent.width == 0 || extent.height == 0 || extent.width > maxSize || extent.height > maxSize)
        throw std::runtime_error("image size " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                                 " is outside what the device supports (1 to " + std::to_string(maxSize) +
                                 " per side)");
    RenderTarget target;
    target.extent = extent;
    target.samples = supportedSamples(ctx, samples);
    const bool msaa = target.samples != VK_SAMPLE_COUNT_1_BIT;
    if (msaa)
        target.msaaColor = createImage(ctx, extent, kColorFormat,
                                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                       target.samples, VK_IMAGE_ASPECT_COLOR_BIT);
    target.color =
        createImage(ctx, extent, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                    VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    target.depth = createImage(ctx, extent, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, target.samples,
                               VK_IMAGE_ASPECT_DEPTH_BIT);
    return target;
}

void destroyRenderTarget(const GpuContext& ctx, RenderTarget& target) {
    destroyImage(ctx, target.msaaColor);
    destroyImage(ctx, target.color);
    destroyImage(ctx, target.depth);
    target = {};
}

} // namespace pf
