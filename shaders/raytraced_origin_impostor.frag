#version 460
#extension GL_GOOGLE_include_directive : require
#include "impostor_surface.glsl"

// The traced-sun pass's origins (engine/field/raytraced_sun_pass.h) of the LOD2
// billboards the sun's square reaches: the fragments impostor.frag keeps,
// each ray from the point of the resting crown it shows, so the crown is
// shadowed by its own full-detail mesh in the field's graph as the shadow
// map shadows it by its impostor's shadow.
layout(location = 0) out vec4 outOrigin;

void main() {
    ImpostorSurface s = impostorSurface();
    outOrigin = raytracedSunOrigin(inRestPos + inDepthAxis * s.relief, s.normal);
}
