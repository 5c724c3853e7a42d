#include "engine/window/text_overlay.h"

#include "engine/vk/pipeline.h"
#include "engine/vk/vk_check.h"

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

// Matches OverlayRect in shaders/text.vert (std430: two vec4).
struct OverlayRect {
    glm::vec4 bounds; // x0, y0, x1, y1 in framebuffer pixels, y down
    glm::vec4 color;  // linear rgba
};

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

TextOverlay createTextOverlay(const GpuContext& ctx) {
    TextOverlay overlay;
    overlay.rects = createHostBuffer(ctx, kMaxOverlayRects * sizeof(OverlayRect), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT,
                                               nullptr};
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = 1;
    layoutInfo.pBindings = &binding;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &layoutInfo, nullptr, &overlay.setLayout));

    overlay.descriptorPool = createDescriptorPool(ctx, {&binding, 1}, 1);

    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = overlay.descriptorPool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &overlay.setLayout;
    VK_CHECK(vkAllocateDescriptorSets(ctx.device, &alloc, &overlay.descriptorSet));

    const VkDescriptorBufferInfo bufferInfo{overlay.rects.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = overlay.descriptorSet;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &bufferInfo;
    vkUpdateDescriptorSets(ctx.device, 1, &write, 0, nullptr);

    const VkPushConstantRange pushRange{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::vec2)};
    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &overlay.setLayout;
    pipelineLayoutInfo.pushConstantRangeCount = 1;
    pipelineLayoutInfo.pPushConstantRanges = &pushRange;
    VK_CHECK(vkCreatePipelineLayout(ctx.device, &pipelineLayoutInfo, nullptr, &overlay.pipelineLayout));

    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(ctx.device, spirv_text_vert);
    desc.fragment = createShaderModule(ctx.device, spirv_text_frag);
    desc.layout = overlay.pipelineLayout;
    desc.colorFormat = kColorFormat;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = desc.depthWrite = false;
    overlay.pipeline = createGraphicsPipeline(ctx.device, desc);
    vkDestroyShaderModule(ctx.device, desc.vertex, nullptr);
    vkDestroyShaderModule(ctx.device, desc.fragment, nullptr);
    return overlay;
}

void destroyTextOverlay(const GpuContext& ctx, TextOverlay& overlay) {
    vkDestroyPipeline(ctx.device, overlay.pipeline, nullptr);
    vkDestroyPipelineLayout(ctx.device, overlay.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(ctx.device, overlay.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(ctx.device, overlay.setLayout, nullptr);
    destroyBuffer(ctx, overlay.rects);
    overlay = {};
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

    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.color.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, target.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &rendering);

    const VkViewport viewport{0.0f, 0.0f, float(target.extent.width), float(target.extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, target.extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, overlay.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, overlay.pipelineLayout, 0, 1, &overlay.descriptorSet,
                            0, nullptr);
    const glm::vec2 framebufferSize{float(target.extent.width), float(target.extent.height)};
    vkCmdPushConstants(cmd, overlay.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(framebufferSize),
                       &framebufferSize);
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
