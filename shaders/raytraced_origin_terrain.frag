#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// The traced-sun pass's origins (engine/field/raytraced_sun_pass.h) of the
// terrain chunks terrain.frag draws: the ground does not sway.
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outOrigin;

void main() {
    outOrigin = raytracedSunOrigin(inWorldPos, normalize(inNormal));
}
