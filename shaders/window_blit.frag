#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/window_blit_layouts.h"

// The frame at the swapchain's size: one bilinear tap of the source
// (engine/window/window_blit.h says in which encoding it is filtered).
layout(set = 0, binding = WINDOW_BLIT_BINDING_SOURCE) uniform sampler2D source;

layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(texture(source, inUv).rgb, 1.0);
}
