// The colour of an LOD2 billboard's fragment (impostor.frag, and
// impostor_sunlit.frag for those the shadow map cannot reach): atlas albedo
// and plant-space normal (both premultiplied by coverage), alpha-tested,
// cross-faded, shaded like LOD0 (plant.frag).
#ifndef IMPOSTOR_COLOUR_GLSL
#define IMPOSTOR_COLOUR_GLSL
#include "field_common.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec2 inUv;
layout(location = 2) flat in uint inLayer;
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inYaw;
layout(location = 6) in vec4 inFog;
layout(location = 7) flat in vec3 inDepthAxis;
layout(location = 0) out vec4 outColor;

// Smaller mips average thin leaves below the 0.5 test; raising alpha with
// the mip level keeps their coverage (impostor_shadow.frag uses the same).
const float kMipAlphaBoost = 0.35;

// `shadowed`: look the sun up in the shadow map; false: in full sun.
void shadeImpostor(bool shadowed) {
    float lod = max(textureQueryLod(atlasColor, inUv).y, 0.0);
    float layer = float(inLayer);
    vec4 color = texture(atlasColor, vec3(inUv, layer));
    if (color.a * (1.0 + kMipAlphaBoost * lod) < 0.5) discard;
    if (fadeDiscards(gl_FragCoord.xy, inFade)) discard;
    vec4 normalDepth = texture(atlasNormal, vec3(inUv, layer));

    vec3 albedo = color.rgb / color.a;
    vec3 n = normalize(normalDepth.rgb / color.a * 2.0 - 1.0);
    n = yawMatrix(inYaw) * n;
    // Impostors are mostly crown: foliage's occlusion and transmission.
    const float occlusion = 0.75;
    // Lit where the surface the frame shows is, not where the quad is: the
    // baked depth (0 front … 1 back) moves the point along the frame's view,
    // so the crown meets its own shadow (impostor_shadow.frag) where its
    // mesh would.
    vec3 surface = inWorldPos + inDepthAxis * (1.0 - 2.0 * normalDepth.a / color.a);
    vec3 shaded = shadowed ? shadeField(albedo, n, surface, occlusion, kFoliageTransmission)
                           : shadeFieldSeen(albedo, n, 1.0, occlusion, kFoliageTransmission);
    outColor = vec4(toneMap(applyVertexFog(shaded, inFog)), 1.0);
}

#endif
