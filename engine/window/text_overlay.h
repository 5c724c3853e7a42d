// On-screen text (frame stats) drawn over a finished frame: stb_easy_font
// turns the lines into axis-aligned rectangles, drawn white at twice the
// font's size with a dark drop shadow, from the top-left corner.
#pragma once

#include "engine/vk/render_target.h"

#include <string>

namespace pf {

// Text beyond this many characters (newlines included) is not shown; the
// vertex buffer is sized for it once, at creation.
constexpr uint32_t kMaxOverlayCharacters = 1024;
constexpr float kOverlayScale = 2.0f;  // font pixels to framebuffer pixels
constexpr float kOverlayMargin = 8.0f; // framebuffer pixels from the top-left corner

struct TextOverlay {
    Buffer rects;           // host-visible storage buffer of rectangles
    uint32_t rectCount = 0; // shadows and glyph strokes of the current text
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Draws into kColorFormat images (RenderTarget::color).
TextOverlay createTextOverlay(const GpuContext& ctx);
void destroyTextOverlay(const GpuContext& ctx, TextOverlay& overlay);

// Replaces the text; '\n' starts a new line, characters outside printable
// ASCII show as '?'. Writes the host-visible buffer directly, so call it only
// while no submitted frame that draws the overlay is still running.
void setOverlayText(TextOverlay& overlay, const std::string& lines);

// Draws the text into target.color, which the renderer left in
// TRANSFER_SRC_OPTIMAL and which is left so again. Records nothing for empty
// text. Must be recorded outside dynamic rendering.
void recordTextOverlay(VkCommandBuffer cmd, const TextOverlay& overlay, const RenderTarget& target);

} // namespace pf
