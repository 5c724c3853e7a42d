#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

layout(location = 0) in vec3 inRay; // sky.vert: the pixel's view ray, not normalised
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(toneMap(skyRadiance(normalize(inRay))), 1.0);
}
