#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// Depth-only billboards for the sun's shadow map (with impostor_shadow.vert):
// the shadow frame's coverage under the same alpha test as impostor.frag,
// fading plants the same dithered share as plant_shadow.frag casts, and
// the depth of the mesh's surface nearest the sun baked in the frame
// instead of the quad's (a nailboard, Schaufler 1997: an impostor whose
// texels carry their depth offset from its plane), so a crown shadows
// itself behind its sunlit leaves as its mesh does.
layout(location = 1) in vec2 inUv;
layout(location = 2) flat in uint inLayer;
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inDepthSpan; // map depth from the quad to the frame's front (toward the sun)

const float kMipAlphaBoost = 0.35; // as impostor.frag

void main() {
    float lod = max(textureQueryLod(impostorShadow, inUv).y, 0.0);
    vec2 coverageDepth = texture(impostorShadow, vec3(inUv, float(inLayer))).rg;
    if (coverageDepth.r * (1.0 + kMipAlphaBoost * lod) < 0.5) discard;
    if (fadeDiscards(gl_FragCoord.xy, inFade)) discard;
    // Baked depth 0 is the frame's front, 1 its back; the quad lies mid-way.
    float depth = coverageDepth.g / coverageDepth.r;
    gl_FragDepth = gl_FragCoord.z + inDepthSpan * (1.0 - 2.0 * depth);
}
