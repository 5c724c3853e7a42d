// The windowed path: render each frame into a RenderTarget with the same
// record function as headless capture, draw it into the swapchain image
// (window_blit.h: scaled up when the render scale is below 1) and present.
// Shows frame time and the render size in the title.
#pragma once

#include "engine/vk/render_target.h"
#include "engine/window/render_scale.h"
#include "engine/window/window.h"

#include <functional>
#include <string>

namespace pf {

// Records one frame into the target, leaving target.color in TRANSFER_SRC_OPTIMAL.
using RecordFrame = std::function<void(VkCommandBuffer cmd, const RenderTarget& target)>;

struct PresentLoopOptions {
    uint32_t maxFrames = 0;          // 0: until the window is closed
    double fixedTimeStep = 0.0;      // seconds per frame; 0: wall-clock time
    std::string screenshotPath;      // PNG of the last frame, when not empty
    Antialiasing antialiasing;       // the renderer's (FieldRenderer::antialiasing())
    RenderScaleSettings renderScale; // the target's share of the window (render_scale.h)
    // Called once the previous frame has finished on the GPU and before this
    // one is recorded: scene time t, seconds since the last frame, the
    // target's size, and the last frame's time in milliseconds (0 at first).
    std::function<void(double t, double dt, VkExtent2D extent, double frameMs)> prepare;
    RecordFrame record;
    std::function<std::string()> titleSuffix; // appended to the window title, e.g. plant counts
};

struct PresentStats {
    uint32_t frames = 0;
    double seconds = 0.0;
    VkExtent2D renderExtent{}; // the render target's size for the last frame (render_scale.h)
};

PresentStats runPresentLoop(const GpuContext& ctx, Window& window, VkSurfaceKHR surface,
                            const PresentLoopOptions& options);

} // namespace pf
