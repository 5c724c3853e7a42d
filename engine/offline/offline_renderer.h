// Frames rendered headless into memory (docs/PYTHON.md "Rendering", the
// plantfield tool's --capture and --frames): a Vulkan context of its own,
// the field renderer and a render target, drawing frame after frame.
//
// A frame carries state to the next: the plants' motion (from rest at the
// first frame's time − 5 s, field_motion.h), the LOD fades, the shadow cache
// and the depth pyramid. So a sequence is deterministic only as a whole, and
// frames go forward: frame i is the same bits whenever frames 0 to i were
// drawn by one renderer in order, which frame(i) does by itself.
#pragma once

#include "engine/field/field_renderer.h"
#include "engine/image/image.h"
#include "engine/vk/device.h"
#include "engine/vk/gpu_timer.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace pf {

struct OfflineSettings {
    VkExtent2D size{1280, 720};
    FieldRenderSettings render;
    GpuOptions gpu;
    std::optional<uint32_t> forcedLod; // every visible plant at this LOD
    // Where the camera is at scene time t; empty: on the scene's camera path (cameraAt).
    std::function<Camera(double t)> camera;
    // Frame i of the sequence is at scene time start + i / fps.
    double start = 0.0;
    double fps = 30.0;
};

// The view of a frame at scene time t, dt seconds after the frame before (0 for the first).
FieldView frameView(const Camera& camera, double t, double dt, bool firstFrame, std::optional<uint32_t> forcedLod);

class OfflineRenderer {
public:
    // Creates the context, the renderer and the target. Throws runtime_error
    // with a clear message when there is no Vulkan device (or not the one
    // asked for), when validation is asked for without the layer, and when the
    // size is beyond the device's images.
    OfflineRenderer(FieldContent content, OfflineSettings settings);
    ~OfflineRenderer();
    OfflineRenderer(const OfflineRenderer&) = delete;
    OfflineRenderer& operator=(const OfflineRenderer&) = delete;

    // Frame `index` of the sequence: the frames before it not drawn yet are
    // drawn first, without being read back. Throws invalid_argument for a
    // frame at or before the last one drawn, or after render() was used.
    RgbaImage frame(uint32_t index);
    // Frame `index` drawn but not read back (what frame() does for the frames
    // before the one asked for), with the same checks.
    void drawFrame(uint32_t index);
    // The frame at scene time t, `camera` in place of the settings' one: the
    // first one drawn starts the plants' motion, a later one continues it by
    // the time since the last frame. Throws invalid_argument when t is before
    // the last frame's time.
    RgbaImage render(double t, const std::optional<Camera>& camera = std::nullopt);

    double timeOfFrame(uint32_t index) const { return settings_.start + index * (1.0 / settings_.fps); }
    uint32_t framesDrawn() const { return framesDrawn_; }
    double lastTime() const { return lastTime_; }     // of the last frame drawn
    double lastWallMs() const { return lastWallMs_; } // recording, submitting and reading back the last captured frame
    // Of the last frame drawn (none drawn: zeros).
    FieldFrameStats stats() const;
    std::vector<ScopeTime> gpuTimes() const;

    const GpuContext& context() const { return ctx_; }
    // What the validation layer says from now on, the objects it finds
    // leaked as this renderer is destroyed included, goes to the returned
    // log: keep it past the renderer to read them.
    std::unique_ptr<ValidationLog> takeValidationLog() { return std::move(ctx_.validationLog); }
    const FieldRenderer& renderer() const { return *renderer_; }
    VkExtent2D size() const { return settings_.size; }

private:
    enum class Mode { unused, frames, times };
    struct Context { // the first member: destroyed last, after whatever was created on it
        GpuContext ctx;
        ~Context() { destroyContext(ctx); }
    };

    void checkFrame(uint32_t index);
    FieldView nextFrameView(uint32_t index);
    RgbaImage capture(const FieldView& view);

    Context owner_;
    GpuContext& ctx_ = owner_.ctx;
    OfflineSettings settings_;
    std::unique_ptr<FieldRenderer> renderer_;
    RenderTarget target_;
    GpuTimer timer_;
    Mode mode_ = Mode::unused;
    uint32_t framesDrawn_ = 0; // with Mode::frames: frames 0 to framesDrawn_ − 1 are drawn
    double lastTime_ = 0.0;
    double lastWallMs_ = 0.0;
};

} // namespace pf
