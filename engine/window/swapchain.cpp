#include "engine/window/swapchain.h"

#include "engine/vk/vk_check.h"

#include <algorithm>
#include <stdexcept>

namespace pf {
namespace {

VkSurfaceFormatKHR chooseFormat(const GpuContext& ctx, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice, surface, &count, formats.data()));
    if (formats.empty()) throw std::runtime_error("the window surface offers no formats");
    // Colours the presentation engine takes as sRGB-encoded (the only
    // colour space every surface has) in a format the frame's bytes fit.
    for (const VkFormat wanted :
         {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats[0];
}

} // namespace

Swapchain createSwapchain(const GpuContext& ctx, VkSurfaceKHR surface, VkExtent2D wanted, Swapchain& old) {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx.physicalDevice, surface, &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
        throw std::runtime_error("the window surface's images cannot be drawn into");

    Swapchain out;
    const VkSurfaceFormatKHR format = chooseFormat(ctx, surface);
    out.format = format.format;
    out.extent = caps.currentExtent.width != UINT32_MAX
                     ? caps.currentExtent
                     : VkExtent2D{std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                                  std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = out.extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always available; paces to the display
    info.clipped = VK_TRUE;
    info.oldSwapchain = old.swapchain;
    VK_CHECK(vkCreateSwapchainKHR(ctx.device, &info, nullptr, &out.swapchain));
    destroySwapchain(ctx, old);

    VK_CHECK(vkGetSwapchainImagesKHR(ctx.device, out.swapchain, &imageCount, nullptr));
    out.images.resize(imageCount);
    VK_CHECK(vkGetSwapchainImagesKHR(ctx.device, out.swapchain, &imageCount, out.images.data()));
    for (VkImage image : out.images) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = out.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VK_CHECK(vkCreateImageView(ctx.device, &view, nullptr, &out.views.emplace_back()));
    }
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    out.renderFinished.resize(imageCount);
    for (VkSemaphore& s : out.renderFinished) VK_CHECK(vkCreateSemaphore(ctx.device, &semaphoreInfo, nullptr, &s));
    return out;
}

void destroySwapchain(const GpuContext& ctx, Swapchain& swapchain) {
    if (!swapchain.swapchain) return;
    vkDeviceWaitIdle(ctx.device);
    for (VkSemaphore s : swapchain.renderFinished) vkDestroySemaphore(ctx.device, s, nullptr);
    for (VkImageView v : swapchain.views) vkDestroyImageView(ctx.device, v, nullptr);
    vkDestroySwapchainKHR(ctx.device, swapchain.swapchain, nullptr);
    swapchain = {};
}

} // namespace pf
