#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

layout(location = 0) in vec2 inNdc;
layout(location = 0) out vec4 outColor;

void main() {
    vec4 nearPoint = frame.invViewProj * vec4(inNdc, 0.0, 1.0);
    vec4 farPoint = frame.invViewProj * vec4(inNdc, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    outColor = vec4(toneMap(skyRadiance(dir)), 1.0);
}
