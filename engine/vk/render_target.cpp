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
    target.resources = GpuResources(ctx);
    target.extent = extent;
    target.samples = supportedSamples(ctx, samples);
    const bool msaa = target.samples != VK_SAMPLE_COUNT_1_BIT;
    if (msaa)
        target.msaaColor = createImage(
            target.resources, {.extent = extent,
                               .format = kColorFormat,
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                               .samples = target.samples});
    target.color =
        createImage(target.resources, {.extent = extent,
                                       .format = kColorFormat,
                                       .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    target.depth = createImage(target.resources, {.extent = extent,
                                                  .format = kDepthFormat,
                                                  .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                                  .aspect = VK_IMAGE_ASPECT_DEPTH_BIT,
                                                  .samples = target.samples});
    return target;
}

void destroyRenderTarget(RenderTarget& target) {
    target.resources.destroy();
    target = {};
}

} // namespace pf
