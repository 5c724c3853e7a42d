#version 460
#extension GL_GOOGLE_include_directive : require
#include "canopy_bake.glsl"

// The canopy the draw reads: per cell its top and mean albedo, or, without
// canopy, the ground sunk by CANOPY_EMPTY_SINK and the mean albedo of its
// neighbours with canopy (the slope down to it blends into their colour).
layout(set = 0, binding = CANOPY_BAKE_BINDING_GROUND, std430) readonly buffer Ground {
    float ground[];
};
layout(set = 0, binding = CANOPY_BAKE_BINDING_CANOPY, std430) writeonly buffer Canopy {
    CanopyCell canopy[];
};

vec3 meanAlbedo(uint c) {
    return vec3(cells[c + 2u], cells[c + 3u], cells[c + 4u]) / (255.0 * float(cells[c + 1u]));
}

void main() {
    uint id = bakeInvocation();
    if (id >= bake.range.y * uint(CANOPY_CELLS)) return;
    uint node = id / uint(CANOPY_CELLS);
    int i = int(id % uint(CLUSTER_GRID)), j = int((id / uint(CLUSTER_GRID)) % uint(CLUSTER_GRID));
    uint c = bakeCell(node, uint(i), uint(j));
    CanopyCell out_;
    out_.ground = floatBitsToUint(ground[id]);
    out_.zero = 0u;
    if (cells[c + 1u] > 0u) {
        out_.height = floatBitsToUint(canopyHeight(cells[c]));
        out_.albedo = packUnorm4x8(vec4(meanAlbedo(c), 1.0));
    } else {
        out_.height = floatBitsToUint(ground[id] - CANOPY_EMPTY_SINK);
        vec3 sum = vec3(0.0);
        float n = 0.0;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                ivec2 q = ivec2(i + di, j + dj);
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(CLUSTER_GRID)))) continue;
                uint k = bakeCell(node, uint(q.x), uint(q.y));
                if (cells[k + 1u] == 0u) continue;
                sum += meanAlbedo(k);
                n += 1.0;
            }
        out_.albedo = packUnorm4x8(vec4(n > 0.0 ? sum / n : vec3(0.0), 0.0));
    }
    canopy[id] = out_;
}
