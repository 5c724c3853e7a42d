// The main colour pass into a RenderTarget, shared by every renderer: clears
// colour and depth, draws into the target's drawn image, and as it ends
// anti-aliases into target.color (the MSAA resolve, or the FXAA pass),
// leaving target.color in TRANSFER_SRC_OPTIMAL for readback or the swapchain
// blit.
#pragma once

#include "engine/vk/render_target.h"

namespace pf {

struct GpuTimer;

// The timer scope of the anti-aliasing after the colour pass's draws: the
// FXAA pass; empty with MSAA (resolved as the rendering ends) and none. The
// field's frame lists it among its scopes (engine/field/field_scopes.h).
inline constexpr const char* kAntialiasScope = "antialias";

// Which part of the colour pass a rendering is: all of it, or the first or
// last of two (occlusion culling draws the plants hidden last frame after
// the depth pyramid of the first part is built, docs/CULLING.md).
enum class TargetPassPart {
    whole, // clears colour and depth; anti-aliased as it ends
    first, // clears them and stores both for the last part
    last,  // loads them; anti-aliased as it ends
};

// Begins dynamic rendering and sets a viewport with negative height, so
// world and clip space stay y-up (pipeline.h: front faces are counter-clockwise).
// A `first` part ends with vkCmdEndRendering, the others with endTargetPass.
void beginTargetPass(VkCommandBuffer cmd, const RenderTarget& target, TargetPassPart part = TargetPassPart::whole);
// Begins dynamic rendering of one colour and one depth attachment over
// `extent` with beginTargetPass's viewport: a pass whose pixels are the
// colour pass's (the traced sun's origins).
void beginFlippedRendering(VkCommandBuffer cmd, VkExtent2D extent, const VkRenderingAttachmentInfo& color,
                           const VkRenderingAttachmentInfo& depth);
// A depth attachment's last frame of tests done and its contents dropped,
// in DEPTH_ATTACHMENT_OPTIMAL for a pass that clears it.
void discardDepthAttachment(VkCommandBuffer cmd, VkImage depth);
// A depth attachment in DEPTH_ATTACHMENT_OPTIMAL cleared to the far plane (1)
// at the start of rendering; `store` keeps it (a shadow map) or drops it.
VkRenderingAttachmentInfo clearedDepthAttachment(VkImageView view, VkAttachmentStoreOp store);
// Begins dynamic rendering into one colour attachment in
// COLOR_ATTACHMENT_OPTIMAL, stored, without depth, and sets an ordinary
// viewport and scissor over `extent`: the full-frame passes after the colour
// pass (FXAA, the window's text overlay). `clear` is used with LOAD_OP_CLEAR.
void beginColorOnlyRendering(VkCommandBuffer cmd, VkImageView view, VkAttachmentLoadOp load, VkExtent2D extent,
                             VkClearColorValue clear = {});
// Ends the rendering, runs the FXAA pass when the target has one, and leaves
// target.color in TRANSFER_SRC_OPTIMAL. With a timer, records the scope
// kAntialiasScope whatever the method, so every frame has the same scopes.
void endTargetPass(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer = nullptr);

} // namespace pf
