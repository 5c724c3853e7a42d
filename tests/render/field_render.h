// Renders scene files headless through the FieldRenderer for the render tests.
#pragma once

#include "engine/field/field_renderer.h"
#include "engine/vk/capture.h"
#include "golden.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::test {

// lavapipe gives the same pixels for the same driver; the tolerance absorbs
// rounding differences between LLVM versions (stated in docs/TESTING.md).
inline const ImageTolerance kFieldTolerance{6, 0.002};

struct FieldShot {
    std::string scene; // file name in data/scenes
    VkExtent2D size{640, 360};
    double time = 0.0;
    std::optional<Camera> camera; // replaces the scene's camera path
    std::optional<uint32_t> forcedLod;
    SunShadows shadows = SunShadows::map;
    Antialiasing antialiasing; // the renderer's default
};

struct FieldShotResult {
    RgbaImage image;
    FieldFrameStats stats;
};

// One frame of a fresh renderer.
FieldShotResult renderField(const GpuContext& ctx, const FieldShot& shot);

// Green-channel darkening by shadows at each pixel: the frame without
// shadows minus the frame with them.
std::vector<int> shadowDarkening(const RgbaImage& lit, const RgbaImage& shadowed);

// One renderer drawing frame after frame, as a window or a --frames sequence does.
class FieldSequence {
public:
    FieldSequence(const GpuContext& ctx, const std::string& scene, VkExtent2D size,
                  const FieldRenderSettings& settings = {});
    ~FieldSequence();
    FieldSequence(const FieldSequence&) = delete;
    FieldSequence& operator=(const FieldSequence&) = delete;

    FieldShotResult frame(const FieldView& view);
    const Scene& scene() const { return scene_; }
    const FieldRenderer& renderer() const { return *renderer_; }

private:
    const GpuContext& ctx_;
    Scene scene_;
    VkExtent2D size_;
    std::unique_ptr<FieldRenderer> renderer_;
    RenderTarget target_;
};

} // namespace pf::test
