#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"

// The terrain mesh, pulled from the TerrainVertex texels by index.
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec4 outFog;
layout(location = 3) out float outBroadPatches; // terrain.frag's broadest noise octave
layout(location = 4) out vec3 outSunMap;        // terrain.frag's shadow lookup (sunMapPosition)

void main() {
    TerrainVertex v = terrainVertexAt(gl_VertexIndex);
    outWorldPos = v.position.xyz;
    outNormal = v.normal.xyz;
    outFog = vertexFog(outWorldPos);
    outBroadPatches = terrainBroadPatches(outWorldPos.xz);
    outSunMap = sunMapPosition(outWorldPos, sunwardNormal(outNormal));
    gl_Position = passViewProj() * vec4(outWorldPos, 1.0);
}
