// The windowed path: render each frame into a RenderTarget with the same
// SceneRenderer::record() as headless capture, blit it to the swapchain and
// present. Shows frame time in the title.
#pragma once

#include "engine/scene_renderer.h"
#include "engine/window.h"

#include <functional>
#include <string>

namespace pf {

struct PresentLoopOptions {
    uint32_t maxFrames = 0;      // 0: until the window is closed
    double fixedTimeStep = 0.0;  // seconds per frame; 0: wall-clock time
    std::string screenshotPath;  // PNG of the last frame, when not empty
    // Uniforms for scene time t and the current framebuffer size.
    std::function<gpu::FrameUniforms(double t, VkExtent2D extent)> frameUniforms;
};

struct PresentStats {
    uint32_t frames = 0;
    double seconds = 0.0;
};

PresentStats runPresentLoop(const GpuContext& ctx, Window& window, VkSurfaceKHR surface, SceneRenderer& renderer,
                            const PresentLoopOptions& options);

} // namespace pf
