#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// The terrain mesh, pulled from the TerrainVertex texels by index.
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec4 outFog;

void main() {
    TerrainVertex v = terrainVertexAt(gl_VertexIndex);
    outWorldPos = v.position.xyz;
    outNormal = v.normal.xyz;
    outFog = vertexFog(outWorldPos);
    gl_Position = passViewProj() * vec4(outWorldPos, 1.0);
}
