// The offscreen images every frame is drawn into, headless or windowed:
// multisampled colour and depth, resolved into a single-sample sRGB image
// that is then read back to PNG or blitted to the swapchain.
#pragma once

#include "engine/vk/resources.h"

namespace pf {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct RenderTarget {
    GpuResources resources; // the images below
    VkExtent2D extent{};
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    Image msaaColor; // only when samples > 1
    Image color;     // resolved result, TRANSFER_SRC_OPTIMAL after a frame
    Image depth;
};

// Throws when the size is zero or beyond the device's image limit. The
// sample count is lowered to what the device supports.
RenderTarget createRenderTarget(const GpuContext& ctx, VkExtent2D extent, VkSampleCountFlagBits samples);
void destroyRenderTarget(RenderTarget& target);

} // namespace pf
