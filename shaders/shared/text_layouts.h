// GPU data of the window's text overlay (engine/window/text_overlay.h),
// shared by GLSL and C++ like layouts.h.
#ifndef PLANTFIELD_SHADERS_TEXT_LAYOUTS_H
#define PLANTFIELD_SHADERS_TEXT_LAYOUTS_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
#endif

// The overlay's one descriptor binding (set 0).
#define TEXT_BINDING_RECTS 0 // OverlayRect[]

// The overlay's viewport is this many pixels square from the top-left
// corner, whatever the target's size (the scissor keeps the drawing inside
// the target): text.vert maps pixels to clip space without being told the
// size. 4096 is the least maxViewportDimensions a device may have.
#define TEXT_VIEWPORT_SIDE 4096

// One stb_easy_font quad (or its shadow) in framebuffer pixels, y down.
struct OverlayRect {
    vec4 bounds; // x0, y0, x1, y1
    vec4 color;  // linear rgba
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::OverlayRect) == 2 * 16);
#endif

#endif
