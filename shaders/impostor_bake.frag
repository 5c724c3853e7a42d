#version 460
#extension GL_GOOGLE_include_directive : require
#include "plant_surface.glsl"

// Albedo and plant-space normal + depth of one impostor frame. Every sample
// written has coverage 1 over a clear-0 background, so the MSAA resolve
// leaves both attachments premultiplied by coverage.
layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inAlbedo;
layout(location = 2) in vec2 inUv;
layout(location = 3) flat in float inKind;
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormalDepth;

void main() {
    bool foliage = inKind > 0.5;
    // The same cut-out as LOD0 (plant.frag), so the impostor shows the same leaves.
    if (foliage && inKind < 1.5 && leafCutOut(inUv)) discard;
    vec3 n = normalize(inNormal);
    if (foliage && !gl_FrontFacing) n = -n; // two-sided: the side the view sees
    outColor = vec4(surfaceAlbedo(inAlbedo, inKind, inUv), 1.0);
    outNormalDepth = vec4(n * 0.5 + 0.5, gl_FragCoord.z);
}
