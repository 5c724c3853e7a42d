// The surface an LOD2 billboard's fragment shows: atlas albedo and plant-
// space normal (both premultiplied by coverage), alpha-tested, cross-faded,
// and the point of the crown it stands for. Read by the colour shaders
// (impostor_color.glsl) and the traced-sun origins (raytraced_origin_impostor.frag).
#ifndef IMPOSTOR_SURFACE_GLSL
#define IMPOSTOR_SURFACE_GLSL
#include "field_common.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec2 inUv;
layout(location = 2) flat in uint inLayer;
layout(location = 3) in vec3 inRestPos; // inWorldPos before the wind's lean
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inYaw;
layout(location = 6) in vec4 inFog;
layout(location = 7) flat in vec3 inDepthAxis;

// Smaller mips average thin leaves below the 0.5 test; raising alpha with
// the mip level keeps their coverage (impostor_shadow.frag uses the same).
const float kMipAlphaBoost = 0.35;

struct ImpostorSurface {
    vec3 albedo;
    vec3 normal;    // world space
    float relief; // along inDepthAxis from the quad to the surface: the baked depth, 0 front … 1 back, as ±1
};

// Discards the fragment outside the crown or faded out.
ImpostorSurface impostorSurface() {
    ImpostorSurface s;
    float lod = max(textureQueryLod(atlasColor, inUv).y, 0.0);
    float layer = float(inLayer);
    vec4 color = texture(atlasColor, vec3(inUv, layer));
    if (color.a * (1.0 + kMipAlphaBoost * lod) < 0.5) discard;
    if (fadeDiscards(gl_FragCoord.xy, inFade)) discard;
    vec4 normalDepth = texture(atlasNormal, vec3(inUv, layer));
    s.albedo = color.rgb / color.a;
    s.normal = yawMatrix(inYaw) * normalize(normalDepth.rgb / color.a * 2.0 - 1.0);
    // Lit where the surface the frame shows is, not where the quad is: the
    // baked depth moves the point along the frame's view, so the crown meets
    // its own shadow where its mesh would.
    s.relief = 1.0 - 2.0 * normalDepth.a / color.a;
    return s;
}

#endif
