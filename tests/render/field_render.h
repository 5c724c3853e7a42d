// Renders scene files headless through the FieldRenderer for the render tests.
#pragma once

#include "engine/field/field_renderer.h"
#include "engine/vk/capture.h"

#include <optional>
#include <string>

namespace pf::test {

struct FieldShot {
    std::string scene; // file name in data/scenes
    VkExtent2D size{640, 360};
    double time = 0.0;
    std::optional<Camera> camera; // replaces the scene's camera path
    std::optional<uint32_t> forcedLod;
    bool shadows = true;
    Antialiasing antialiasing; // the renderer's default
};

struct FieldShotResult {
    RgbaImage image;
    FieldFrameStats stats;
};

FieldShotResult renderField(const GpuContext& ctx, const FieldShot& shot);

} // namespace pf::test
