#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// The traced-sun pass's origins (engine/field/raytraced_sun_pass.h) of plant
// meshes: the fragments plant.frag keeps, each where its sun ray starts.
layout(location = 1) in vec3 inNormal;
layout(location = 3) in vec2 inUv;
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inKind;
layout(location = 7) in vec3 inRestPos;
layout(location = 0) out vec4 outOrigin;

void main() {
    if (plantFragmentDiscarded(gl_FragCoord.xy, inFade, inKind, inUv)) discard;
    outOrigin = raytracedSunOrigin(inRestPos, normalize(inNormal));
}
