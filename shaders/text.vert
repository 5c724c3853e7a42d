#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/text_layouts.h"

// The text overlay's rectangles (stb_easy_font quads), pulled from a storage
// buffer: six vertices, two triangles, a rectangle. Positions are pixels with
// y down, in the fixed TEXT_VIEWPORT_SIDE viewport. No push constant gives
// the target's size: lavapipe recompiles a vertex shader that reads push
// constants each time they change before a draw (it inlines their values),
// which cost the window a shader compilation every frame.
layout(std430, set = 0, binding = TEXT_BINDING_RECTS) readonly buffer OverlayRects {
    OverlayRect rects[];
};

layout(location = 0) flat out vec4 outColor;

const int kCorner[6] = int[6](0, 1, 2, 2, 1, 3); // bit 0: right, bit 1: bottom

void main() {
    OverlayRect rect = rects[gl_VertexIndex / 6];
    int corner = kCorner[gl_VertexIndex % 6];
    vec2 pixel = vec2((corner & 1) != 0 ? rect.bounds.z : rect.bounds.x,
                      (corner & 2) != 0 ? rect.bounds.w : rect.bounds.y);
    // Vulkan's clip space already has y down, so pixels map without a flip.
    gl_Position = vec4(pixel / float(TEXT_VIEWPORT_SIDE) * 2.0 - 1.0, 0.0, 1.0);
    outColor = rect.color;
}
