// The offscreen images every frame is drawn into, headless or windowed, and
// how the frame is anti-aliased (antialiasing.h): with FXAA the colour pass
// draws one sample a pixel into an image the FXAA pass then reads; with MSAA
// it draws several, resolved as it ends; with none it draws straight into
// the sRGB `color` image, which every method leaves finished, to be read back
// to PNG or blitted to the swapchain.
#pragma once

#include "engine/vk/antialiasing.h"
#include "engine/vk/depth_pyramid.h"
#include "engine/vk/fxaa_pass.h"
#include "engine/vk/resources.h"

namespace pf {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct RenderTarget {
    GpuResources resources; // the images and the FXAA pass below
    VkExtent2D extent{};
    Antialiasing antialiasing;                             // as made: supportedAntialiasing()
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT; // of the colour pass: its colour and depth
    Image msaaColor;      // msaa only: what the colour pass draws, resolved into `color`
    Image fxaaInput;      // fxaa only: what the colour pass draws, one sample, read by `fxaa`
    FxaaPass fxaa;        // fxaa only: draws `color` from fxaaInput
    Image color;          // the finished frame, TRANSFER_SRC_OPTIMAL after a frame
    Image depth;          // sampled by the depth pyramid's reduction
    DepthPyramid pyramid; // of `depth`, for occlusion culling (depth_pyramid.h)
};

// `wanted` with its MSAA sample count lowered to the most the device
// supports for both colour and depth (at worst 1, which draws as none). A
// renderer makes its pipelines for this, as createRenderTarget makes its
// images.
Antialiasing supportedAntialiasing(const GpuContext& ctx, Antialiasing wanted);

// Throws when the size is zero or beyond the device's image limit.
RenderTarget createRenderTarget(const GpuContext& ctx, VkExtent2D extent, Antialiasing antialiasing);
void destroyRenderTarget(RenderTarget& target);

// The image the colour pass draws into: msaaColor, fxaaInput or color.
const Image& drawnColor(const RenderTarget& target);

} // namespace pf
