#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/canopy_mesh.h"
#include "field_common.glsl"

// A far node's canopy (canopy_mesh.h): instance i is the camera's i-th far
// node; vertices at cell centres take the cell's top (or the sunk ground
// where it has none), the border ring the edge cells', the skirt sinks
// below the ground. Normals from the differences of neighbouring tops.
layout(set = 0, binding = FIELD_BINDING_CLUSTER_NODES) uniform usamplerBuffer clusterNodeTexels; // ClusterNode[]
layout(set = 0, binding = FIELD_BINDING_CANOPY) uniform usamplerBuffer canopyTexels;             // CanopyCell[]
layout(set = 0, binding = FIELD_BINDING_CANOPY_FAR) uniform usamplerBuffer canopyFarTexels;      // uint

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outAlbedo;
layout(location = 3) out vec4 outFog;

uvec4 cellAt(uint node, ivec2 cell) {
    ivec2 c = clamp(cell, ivec2(0), ivec2(CLUSTER_GRID - 1));
    return texelFetch(canopyTexels, int(node) * CANOPY_CELLS + c.y * CLUSTER_GRID + c.x);
}

float topAt(uint node, ivec2 cell) {
    return uintBitsToFloat(cellAt(node, cell).x);
}

void main() {
    uint node = texelFetch(canopyFarTexels, gl_InstanceIndex).x;
    vec4 square = floatTexel(clusterNodeTexels, int(node) * CLUSTER_NODE_TEXELS + 2);
    uint v = uint(gl_VertexIndex);
    bool skirt = v >= uint(CANOPY_GRID_VERTICES);
    uvec2 g = skirt ? canopyRingVertex(v - uint(CANOPY_GRID_VERTICES))
                    : uvec2(v % uint(CANOPY_GRID_SIDE), v / uint(CANOPY_GRID_SIDE));
    ivec2 cell = ivec2(g) - 1;
    uvec4 c = cellAt(node, cell);
    vec2 xz = square.xy + clamp((vec2(g) - 0.5) * square.w, vec2(0.0), vec2(square.z));
    float y = skirt ? uintBitsToFloat(c.y) - CANOPY_EMPTY_SINK : uintBitsToFloat(c.x);
    outWorldPos = vec3(xz.x, y, xz.y);

    if (skirt) {
        uint last = uint(CANOPY_GRID_SIDE - 1);
        outNormal = vec3(g.x == 0u ? -1.0 : (g.x == last ? 1.0 : 0.0), 0.0,
                         g.y == 0u ? -1.0 : (g.y == last ? 1.0 : 0.0));
    } else {
        float dx = topAt(node, cell + ivec2(1, 0)) - topAt(node, cell - ivec2(1, 0));
        float dz = topAt(node, cell + ivec2(0, 1)) - topAt(node, cell - ivec2(0, 1));
        outNormal = vec3(-dx, 2.0 * square.w, -dz);
    }
    outAlbedo = unpackUnorm4x8(c.z).rgb;
    outFog = vertexFog(outWorldPos);
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
}
