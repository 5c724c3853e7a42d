#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

// A square ground plane centred on the origin, made from gl_VertexIndex.
layout(location = 0) out vec3 outWorldPos;

void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 xz = corners[gl_VertexIndex] * frame.fog.y;
    outWorldPos = vec3(xz.x, 0.0, xz.y);
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
}
