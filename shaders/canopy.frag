#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// Far nodes' canopy: opaque (no discard, so a software rasteriser's early
// depth test rejects what lies behind it), lit like the impostors it
// replaces: foliage's transmission, the crown's occlusion.
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inAlbedo;
layout(location = 3) in vec4 inFog;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 shaded = shadeField(inAlbedo, normalize(inNormal), inWorldPos, 0.75, kFoliageTransmission);
    outColor = vec4(toneMap(applyVertexFog(shaded, inFog)), 1.0);
}
