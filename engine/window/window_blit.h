// The window's last pass: the finished frame (RenderTarget::color, rendered
// at the dynamic render scale's share of the window, render_scale.h) drawn
// over the whole swapchain image with one bilinear tap a pixel
// (shaders/fullscreen.vert, shaders/window_blit.frag).
//
// A draw rather than vkCmdBlitImage, so the filter may work on the frame's
// encoded bytes: the target is sRGB and a blit filters sRGB texels in linear
// light, decoding each one, which on lavapipe (Mesa 22.3) cost about 2.5 ms
// of a 64 ms window frame at 640×360 → 1280×720 more than a nearest-texel
// blit (docs/BENCHMARKS.md). With a UNORM swapchain the source is read
// through a UNORM view, so its gamma-encoded bytes are filtered as they are
// (as FXAA blends them) and written unchanged; with an sRGB swapchain it is
// read through its own sRGB format and filtered in linear light, as a blit
// would.
#pragma once

#include "engine/vk/resources.h"

namespace pf {

struct WindowBlit {
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE; // the source, through windowBlitSourceFormat's view
};

// The format the source is read through for an output of `outputFormat`:
// sRGB for an sRGB output, else UNORM (the encoded bytes).
VkFormat windowBlitSourceFormat(VkFormat outputFormat);

// Owned by `owner`. `source`: SAMPLED usage, 4 bytes a texel, made with
// VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT (RenderTarget::color is).
WindowBlit createWindowBlit(GpuResources& owner, const Image& source, VkFormat outputFormat);

// Draws every pixel of `output` (COLOR_ATTACHMENT_OPTIMAL, its contents not
// read, `extent` its size) from the source, which must be in
// SHADER_READ_ONLY_OPTIMAL and visible to fragment shaders.
void recordWindowBlit(VkCommandBuffer cmd, const WindowBlit& blit, VkImageView output, VkExtent2D extent);

} // namespace pf
