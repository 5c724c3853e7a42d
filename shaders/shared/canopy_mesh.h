// The mesh one far node is drawn with (docs/CLUSTERS.md), shared by
// canopy.vert and pf::canopyMeshIndices: a grid of (CLUSTER_GRID + 2)²
// vertices, one at each canopy cell's centre and a border ring on the node's
// square, then a skirt: a copy of the border ring sunk below the ground, so
// the sides of a node read as a wall of forest and neighbouring nodes leave
// no crack between them.
#ifndef PLANTFIELD_SHADERS_CANOPY_MESH_H
#define PLANTFIELD_SHADERS_CANOPY_MESH_H

#include "cluster_layouts.h"

#ifdef __cplusplus
namespace gpu {
using uvec2 = glm::uvec2;
#define CANOPY_MESH_FN inline
#else
#define CANOPY_MESH_FN
#endif

#define CANOPY_GRID_SIDE (CLUSTER_GRID + 2) // grid vertices along a side
#define CANOPY_GRID_VERTICES (CANOPY_GRID_SIDE * CANOPY_GRID_SIDE)
#define CANOPY_RING_VERTICES (4 * (CANOPY_GRID_SIDE - 1)) // the border of the grid, once round
#define CANOPY_VERTICES (CANOPY_GRID_VERTICES + CANOPY_RING_VERTICES)

// Grid coordinates of border vertex k, going round from (0, 0) along +x.
CANOPY_MESH_FN uvec2 canopyRingVertex(uint k) {
    uint edge = k / uint(CANOPY_GRID_SIDE - 1), t = k % uint(CANOPY_GRID_SIDE - 1), last = uint(CANOPY_GRID_SIDE - 1);
    if (edge == 0u) return uvec2(t, 0u);
    if (edge == 1u) return uvec2(last, t);
    if (edge == 2u) return uvec2(last - t, last);
    return uvec2(0u, last - t);
}

CANOPY_MESH_FN uint canopyGridVertex(uvec2 g) { return g.y * uint(CANOPY_GRID_SIDE) + g.x; }

#ifdef __cplusplus
} // namespace gpu
#endif
#undef CANOPY_MESH_FN

#endif
