#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

// A full-screen triangle at the far plane, carrying each corner's view ray.
// The world-space ray through a pixel, far point minus near point, is an
// affine function of its NDC position for a perspective projection, so the
// rasteriser's interpolation (w = 1 at every corner: linear in the screen)
// gives every pixel its own ray, up to rounding, without the per-pixel
// inverse projection.
layout(location = 0) out vec3 outRay;

void main() {
    vec2 ndc = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
    vec4 nearPoint = frame.invViewProj * vec4(ndc, 0.0, 1.0);
    vec4 farPoint = frame.invViewProj * vec4(ndc, 1.0, 1.0);
    outRay = farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w;
    gl_Position = vec4(ndc, 1.0, 1.0);
}
