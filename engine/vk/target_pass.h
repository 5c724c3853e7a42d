// The main colour pass into a RenderTarget, shared by every renderer: clears
// colour and depth, resolves multisampling into target.color, and leaves
// target.color in TRANSFER_SRC_OPTIMAL for readback or the swapchain blit.
#pragma once

#include "engine/vk/render_target.h"

namespace pf {

// Begins dynamic rendering and sets a viewport with negative height, so
// world and clip space stay y-up (pipeline.h: front faces are counter-clockwise).
void beginTargetPass(VkCommandBuffer cmd, const RenderTarget& target);
// A depth attachment in DEPTH_ATTACHMENT_OPTIMAL cleared to the far plane (1)
// at the start of rendering; `store` keeps it (a shadow map) or drops it.
VkRenderingAttachmentInfo clearedDepthAttachment(VkImageView view, VkAttachmentStoreOp store);
void endTargetPass(VkCommandBuffer cmd, const RenderTarget& target);

} // namespace pf
