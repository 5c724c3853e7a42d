#version 460
#extension GL_GOOGLE_include_directive : require
#include "canopy_bake.glsl"

// One level of inner nodes from their children (the level below, already
// baked): one invocation per cell, which covers 2×2 cells of the child in
// its quadrant: the highest top, the plants and albedo sums added.
void main() {
    uint id = bakeInvocation();
    if (id >= bake.range.y * uint(CANOPY_CELLS)) return;
    uint node = bake.range.x + id / uint(CANOPY_CELLS);
    uint i = id % uint(CLUSTER_GRID), j = (id / uint(CLUSTER_GRID)) % uint(CLUSTER_GRID);
    const uint halfGrid = uint(CLUSTER_GRID / 2);
    uint child = nodes[node].children[(i >= halfGrid ? 1u : 0u) + (j >= halfGrid ? 2u : 0u)];
    if (child == CLUSTER_NONE) return; // the cells stay zero: no canopy
    uint top = 0u;
    uint sums[4] = uint[4](0u, 0u, 0u, 0u);
    for (uint dj = 0u; dj < 2u; ++dj)
        for (uint di = 0u; di < 2u; ++di) {
            uint c = bakeCell(child, (i % halfGrid) * 2u + di, (j % halfGrid) * 2u + dj);
            top = max(top, cells[c]);
            for (uint w = 0u; w < 4u; ++w) sums[w] += cells[c + 1u + w];
        }
    uint c = bakeCell(node, i, j);
    cells[c] = top;
    for (uint w = 0u; w < 4u; ++w) cells[c + 1u + w] = sums[w];
}
