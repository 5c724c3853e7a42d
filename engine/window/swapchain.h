// The window's swapchain. Frames are rendered into a RenderTarget and
// blitted into swapchain images, so presentation adds no rendering code.
#pragma once

#include "engine/vk/device.h"

#include <vector>

namespace pf {

struct Swapchain {
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    std::vector<VkImage> images;
    std::vector<VkSemaphore> renderFinished; // one per image: presentation holds it until the image returns
};

// Replaces `old` (which may be empty) by a swapchain of the given size.
Swapchain createSwapchain(const GpuContext& ctx, VkSurfaceKHR surface, VkExtent2D wanted, Swapchain& old);
void destroySwapchain(const GpuContext& ctx, Swapchain& swapchain);

} // namespace pf
