// The colour of an LOD2 billboard's fragment (impostor.frag, and
// impostor_sunlit.frag for those the sun's shadows cannot reach), shaded
// like LOD0 (plant.frag).
#ifndef IMPOSTOR_COLOR_GLSL
#define IMPOSTOR_COLOR_GLSL
#include "impostor_surface.glsl"

layout(location = 0) out vec4 outColor;

// `shadowed`: look the sun up (shadow map or traced rays); false: in full sun.
void shadeImpostor(bool shadowed) {
    ImpostorSurface s = impostorSurface();
    // Impostors are mostly crown: foliage's occlusion and transmission.
    const float occlusion = 0.75;
    vec3 surface = inWorldPos + inDepthAxis * s.relief;
    float sun = shadowed ? sunVisibilityOf(gl_FragCoord.xy, sunMapPosition(surface, sunwardNormal(s.normal))) : 1.0;
    vec3 shaded = shadeFieldSeen(s.albedo, s.normal, sun, occlusion, kFoliageTransmission);
    outColor = vec4(toneMap(applyVertexFog(shaded, inFog)), 1.0);
}

#endif
