#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// Depth-only plants for the sun's shadow map: leaves cast their cut-out
// shape, and fading plants the same dithered share as they are drawn with.
layout(location = 2) in vec3 inAlbedo;
layout(location = 3) in vec2 inUv;
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inKind;

void main() {
    if (plantFragmentDiscarded(gl_FragCoord.xy, inFade, inKind, inUv)) discard;
}
