// Headless frames: render into a RenderTarget and read the result back.
#pragma once

#include "engine/image.h"
#include "engine/scene_renderer.h"

namespace pf {

// Records the frame and a copy of the resolved colour into a host buffer,
// submits, waits, and returns the pixels (top row first).
RgbaImage captureFrame(const GpuContext& ctx, const SceneRenderer& renderer, const RenderTarget& target);

} // namespace pf
