#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// Bark and foliage of LOD0/LOD1 plants: the LOD cross-fade dither, the leaf
// card cut-out, two-sided foliage lit through its back, sun shadow, fog.
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inAlbedo;
layout(location = 3) in vec2 inUv;
layout(location = 4) flat in uint inFade;
layout(location = 5) flat in float inKind;
layout(location = 6) in vec4 inFog;
layout(location = 0) out vec4 outColor;

void main() {
    if (plantFragmentDiscarded(gl_FragCoord.xy, inFade, inKind, inUv)) discard;
    bool foliage = inKind > 0.5;

    vec3 n = normalize(inNormal);
    if (foliage && !gl_FrontFacing) n = -n; // two-sided: light the side we see
    vec3 albedo = surfaceAlbedo(inAlbedo, inKind, inUv);
    // Foliage inside a crown sees less sky; bark near the ground too.
    float occlusion = foliage ? 0.75 : 0.85;
    float sun = sunVisibilityOf(gl_FragCoord.xy, sunMapPosition(inWorldPos, sunwardNormal(n)));
    vec3 color = shadeFieldSeen(albedo, n, sun, occlusion, foliage ? kFoliageTransmission : 0.0);
    outColor = vec4(toneMap(applyVertexFog(color, inFog)), 1.0);
}
