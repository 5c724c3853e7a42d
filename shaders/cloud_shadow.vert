#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
#include "shared/cloud_layouts.h"
#include "shared/field_layouts.h"

// The terrain mesh again (as terrain.vert pulls it), for its clouds' shadows.
layout(set = 0, binding = CLOUD_SHADOW_BINDING_TERRAIN) uniform usamplerBuffer terrainTexels; // TerrainVertex[]

layout(location = 0) out vec3 outWorldPos;

void main() {
    outWorldPos = uintBitsToFloat(texelFetch(terrainTexels, gl_VertexIndex * TERRAIN_VERTEX_TEXELS)).xyz;
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
}
