#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// Depth-only billboards for the sun's shadow map (with impostor_shadow.vert):
// the shadow frame's coverage under the same alpha test as impostor.frag,
// and fading plants the same dithered share as plant_shadow.frag casts.
layout(location = 1) in vec2 inUv;
layout(location = 2) flat in uint inLayer;
layout(location = 4) flat in uint inFade;

const float kMipAlphaBoost = 0.35; // as impostor.frag

void main() {
    float lod = max(textureQueryLod(impostorShadow, inUv).y, 0.0);
    float coverage = texture(impostorShadow, vec3(inUv, float(inLayer))).r;
    if (coverage * (1.0 + kMipAlphaBoost * lod) < 0.5) discard;
    if (fadeDiscards(gl_FragCoord.xy, inFade)) discard;
}
