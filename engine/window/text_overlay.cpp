#include "engine/window/text_overlay.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "shaders/shared/text_layouts.h"

#include <glm/glm.hpp>

#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" // the header's width/height/spacing helpers
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include "shaders/text_frag.spv.h"
#include "shaders/text_vert.spv.h"

namespace pf {
namespace {

using gpu::OverlayRect;

// The most strokes (quads) any stb_easy_font glyph is made of.
constexpr uint32_t kMaxQuadsPerCharacter = 11;
// Every stroke is drawn twice: its shadow first, then itself.
constexpr uint32_t kMaxOverlayRects = 2 * kMaxOverlayCharacters * kMaxQuadsPerCharacter;

constexpr glm::vec4 kTextColor{1.0f, 1.0f, 1.0f, 1.0f};
constexpr glm::vec4 kShadowColor{0.0f, 0.0f, 0.0f, 1.0f};
constexpr float kShadowOffset = kOverlayScale; // one font pixel down and right

// stb_easy_font writes four of these a quad.
struct StbVertex {
    float x, y, z;
    unsigned char color[4];
};
static_assert(sizeof(StbVertex) == 16);

} // namespace

TextOverlay createTextOverlay(GpuResources& owner) {
    TextOverlay overlay;
    overlay.rects = createHostBuffer(owner, kMaxOverlayRects * sizeof(OverlayRect), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    const DescriptorBinding table[] = {storageBuffer(TEXT_BINDING_RECTS, VK_SHADER_STAGE_VERTEX_BIT, overlay.rects)};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    overlay.descriptorSet = createSet(owner, setLayout, table);
    overlay.pipelineLayout = createPipelineLayout(owner, setLayout);

    overlay.pipeline =
        createColorOnlyPipeline(owner, spirv_text_vert, spirv_text_frag, overlay.pipelineLayout, kColorFormat);
    return overlay;
}

void setOverlayText(TextOverlay& overlay, const std::string& lines) {
    // stb_easy_font indexes its glyph table by character, so anything it has
    // no glyph for must not reach it.
    std::string text = lines.substr(0, kMaxOverlayCharacters);
    for (char& c : text)
        if (c != '\n' && (c < 32 || c > 126)) c = '?';

    std::vector<StbVertex> quads(size_t(kMaxOverlayCharacters) * kMaxQuadsPerCharacter * 4);
    const uint32_t quadCount = uint32_t(
        stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, quads.data(), int(quads.size() * sizeof(StbVertex))));

    // Host writes before vkQueueSubmit are visible to the GPU without a barrier.
    OverlayRect* rects = static_cast<OverlayRect*>(overlay.rects.mapped);
    for (uint32_t q = 0; q < quadCount; ++q) {
        // Vertices 0 and 2 of each quad are its top-left and bottom-right corners.
        const StbVertex& topLeft = quads[4 * q];
        const StbVertex& bottomRight = quads[4 * q + 2];
        const glm::vec4 bounds =
            kOverlayMargin + kOverlayScale * glm::vec4(topLeft.x, topLeft.y, bottomRight.x, bottomRight.y);
        rects[q] = {bounds + kShadowOffset, kShadowColor};
        rects[quadCount + q] = {bounds, kTextColor};
    }
    overlay.rectCount = 2 * quadCount;
}

void recordTextOverlay(VkCommandBuffer cmd, const TextOverlay& overlay, const RenderTarget& target) {
    if (overlay.rectCount == 0) return;

    // The renderer's last barrier made its colour writes available and moved
    // the image to TRANSFER_SRC for the transfer stage. Waiting on that stage
    // chains onto it and also orders the overlay after any copy out of the
    // image (write-after-read: an execution dependency, no access mask). The
    // overlay loads the frame, so the attachment is read as well as written.
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});

    beginColorOnlyRendering(cmd, target.color.view, VK_ATTACHMENT_LOAD_OP_LOAD, target.extent);
    // The scissor stays the target's: the viewport may reach past it.
    const VkViewport viewport{0.0f, 0.0f, float(TEXT_VIEWPORT_SIDE), float(TEXT_VIEWPORT_SIDE), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, overlay.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, overlay.pipelineLayout, 0, 1, &overlay.descriptorSet,
                            0, nullptr);
    vkCmdDraw(cmd, 6 * overlay.rectCount, 1, 0, 0);
    vkCmdEndRendering(cmd);

    // Back to what the renderer leaves, for the blit to the swapchain or the
    // copy to a readback buffer.
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
}

} // namespace pf
