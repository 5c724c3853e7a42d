// Headless frames: render into a RenderTarget and read the result back.
#pragma once

#include "engine/image/image.h"
#include "engine/vk/render_target.h"

#include <functional>

namespace pf {

// Records the frame and a copy of the resolved colour into a host buffer,
// submits, waits, and returns the pixels (top row first).
RgbaImage captureFrame(const GpuContext& ctx, const RenderTarget& target,
                       const std::function<void(VkCommandBuffer, const RenderTarget&)>& record);

} // namespace pf
