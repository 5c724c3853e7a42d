#version 460
#extension GL_GOOGLE_include_directive : require
#include "plant_surface.glsl"

// Coverage and depth of one impostor shadow frame (with impostor_bake.vert):
// every sample the mesh covers writes 1 and the depth of its surface
// nearest the sun over a clear-0 background, so the MSAA resolve leaves the
// share of the texel the mesh covers and that depth premultiplied by it.
// Leaves are cut as plant.frag cuts LOD0, so the frame casts the shadow the
// mesh casts.
layout(location = 2) in vec2 inUv;
layout(location = 3) flat in float inKind;
layout(location = 0) out vec2 outCoverageDepth;

void main() {
    if (inKind > 0.5 && inKind < 1.5 && leafCutOut(inUv)) discard;
    outCoverageDepth = vec2(1.0, gl_FragCoord.z);
}
