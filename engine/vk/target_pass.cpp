#include "engine/vk/target_pass.h"

#include "engine/vk/gpu_timer.h"

namespace pf {

VkRenderingAttachmentInfo clearedDepthAttachment(VkImageView view, VkAttachmentStoreOp store) {
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = store;
    depth.clearValue.depthStencil = {1.0f, 0};
    return depth;
}

namespace {

// Previous contents are discarded (UNDEFINED): the colour image waits only
// for the last frame's copy or blit out of it, an MSAA or FXAA image for
// the last frame's writes and reads, depth for its last writes.
void discardPreviousFrame(VkCommandBuffer cmd, const RenderTarget& target) {
    const Image& drawn = drawnColor(target);
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    if (drawn.image != target.color.image)
        imageBarrier(cmd, drawn.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    discardDepthAttachment(cmd, target.depth.image);
}

} // namespace

void discardDepthAttachment(VkCommandBuffer cmd, VkImage depth) {
    const VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    imageBarrier(cmd, depth, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthStages,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
}

void beginTargetPass(VkCommandBuffer cmd, const RenderTarget& target, TargetPassPart part) {
    const bool msaa = target.samples != VK_SAMPLE_COUNT_1_BIT;
    const bool load = part == TargetPassPart::last;
    const bool resolve = msaa && part != TargetPassPart::first;
    const Image& drawn = drawnColor(target);
    // The last part's colour writes follow the first part's (its depth
    // waits in recordDepthPyramid, which reads it in between).
    if (load)
        imageBarrier(cmd, drawn.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    else
        discardPreviousFrame(cmd, target);

    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = drawn.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = resolve ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    if (resolve) {
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = target.color.view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    VkRenderingAttachmentInfo depth =
        clearedDepthAttachment(target.depth.view, part == TargetPassPart::first ? VK_ATTACHMENT_STORE_OP_STORE
                                                                                : VK_ATTACHMENT_STORE_OP_DONT_CARE);
    if (load) depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    beginFlippedRendering(cmd, target.extent, color, depth);
}

void beginFlippedRendering(VkCommandBuffer cmd, VkExtent2D extent, const VkRenderingAttachmentInfo& color,
                           const VkRenderingAttachmentInfo& depth) {
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);
    // Negative height flips y so world and clip space stay y-up.
    const VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void beginColorOnlyRendering(VkCommandBuffer cmd, VkImageView view, VkAttachmentLoadOp load, VkExtent2D extent,
                             VkClearColorValue clear) {
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = load;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = clear;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &rendering);

    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void endTargetPass(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) {
    vkCmdEndRendering(cmd);

    {
        const TimedScope scope(cmd, timer, kAntialiasScope);
        if (target.antialiasing.method == AntialiasMethod::fxaa) {
            imageBarrier(cmd, target.fxaaInput.image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
            recordFxaaPass(cmd, target.fxaa);
        }
    }

    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
}

} // namespace pf
