// The window's swapchain. Frames are rendered into a RenderTarget and drawn
// into swapchain images by the window blit (window_blit.h), so presentation
// adds no rendering code to the renderer.
#pragma once

#include "engine/vk/device.h"

#include <vector>

namespace pf {

struct Swapchain {
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    std::vector<VkImage> images;
    std::vector<VkImageView> views;          // one per image, in `format`: the window blit draws into them
    std::vector<VkSemaphore> renderFinished; // one per image: presentation holds it until the image returns
};

// Replaces `old` (which may be empty) by a swapchain of the given size, of
// colour-attachment images in a UNORM format of 8 bits a channel where the
// surface offers one (the window blit writes the frame's sRGB-encoded
// bytes as they are), else in an sRGB one, else in its first format.
Swapchain createSwapchain(const GpuContext& ctx, VkSurfaceKHR surface, VkExtent2D wanted, Swapchain& old);
void destroySwapchain(const GpuContext& ctx, Swapchain& swapchain);

} // namespace pf
