// GPU data layouts of the field's cluster hierarchy (docs/CLUSTERS.md), shared by GLSL and C++:
// the quadtree of terrain tiles built at load (engine/scene/clusters.h), the
// per-frame cut through it (cluster.comp, cluster_select.h) and the lists of
// near plants the per-plant cull runs over.
#ifndef PLANTFIELD_SHADERS_CLUSTER_LAYOUTS_H
#define PLANTFIELD_SHADERS_CLUSTER_LAYOUTS_H

#include "field_layouts.h"

#ifdef __cplusplus
namespace gpu {
#endif

// No node (a parent of the root, a quadrant without plants).
#define CLUSTER_NONE 0xFFFFFFFFu

// Canopy cells along each side of a node's square (its far representation).
#define CLUSTER_GRID 16
// Corners of the canopy grid along a side, and in all.
#define CLUSTER_CORNERS_SIDE (CLUSTER_GRID + 1)
#define CLUSTER_CORNERS (CLUSTER_CORNERS_SIDE * CLUSTER_CORNERS_SIDE)

// One node of the quadtree: a square of the terrain and the plants standing in it.
struct ClusterNode {
    vec4 boxMin;    // xyz the box of its plants' bounding spheres (world, m), w 0
    vec4 boxMax;    // xyz, w 0
    vec4 square;    // x min x, y min z of its terrain square, z side (m), w canopy cell size (side / CLUSTER_GRID)
    uvec4 range;    // x first plant, y plants, z parent node (CLUSTER_NONE at the root), w level (0: a leaf)
    uvec4 children; // the nodes of its four quadrants (x: -x-z, y: +x-z, z: -x+z, w: +x+z), CLUSTER_NONE if empty
};

// How the cut through the quadtree is chosen (ClusterUniforms::counts.z).
#define CLUSTER_CUT_AUTO 0u     // far where a node's canopy cell is below the threshold in pixels and its parent's not
#define CLUSTER_CUT_ALL_NEAR 1u // every leaf in view is near: every plant goes through the per-plant cull
#define CLUSTER_CUT_ALL_FAR 2u  // every leaf in view is drawn as its canopy, no plant per plant
#define CLUSTER_CUT_BOX_ONLY 3u // the sun's casters: leaves meeting the planes are near, nothing is far

// What the cut makes of a node this frame (clusterDecision).
#define CLUSTER_CULLED 0u  // outside the planes
#define CLUSTER_COVERED 1u // drawn by a far ancestor, or by its descendants
#define CLUSTER_FAR 2u     // drawn as its canopy
#define CLUSTER_NEAR 3u    // a leaf whose plants go through the per-plant cull

// Bound as a read-only storage buffer, not a uniform block (docs/ARCHITECTURE.md,
// "What a shader may branch on").
struct ClusterUniforms {
    vec4 frustum[6]; // planes as CullUniforms::frustum (or the sun's box for CLUSTER_CUT_BOX_ONLY)
    vec4 camera;     // xyz position, w pixels per metre at one metre (CullUniforms::camera)
    uvec4 counts;    // x nodes, y leaves (nodes [0, y)), z CLUSTER_CUT_*, w 1 on the first frame
    vec4 threshold;  // x canopy cell pixels below which a node may be far, yzw 0
    uvec4 limits;    // x maxComputeWorkGroupCount[0] (rows of the near dispatch), yzw 0
};

// The near plants, in chunks of at most CULL_GROUP_SIZE plants of one leaf:
// one cull workgroup each (vkCmdDispatchIndirect on `dispatch`).
#define NEAR_CHUNK_RESTART_BIT 0x80000000u // the leaf was not near last frame: its plants' LOD state starts settled
#define NEAR_CHUNK_COUNT_MASK 0x7FFFFFFFu
#define NEAR_CHUNK_HEADER_BYTES 16 // count, then the VkDispatchIndirectCommand (3 uints)
#define NEAR_CHUNK_DISPATCH_OFFSET 4

// Counters of the cluster pass (readback for FieldFrameStats).
#define CLUSTER_STAT_FAR 0         // nodes drawn as canopy
#define CLUSTER_STAT_NEAR_LEAVES 1 // leaves whose plants the per-plant cull ran over
#define CLUSTER_STAT_NEAR_PLANTS 2 // plants in those leaves
#define CLUSTER_STAT_FAR_PLANTS 3  // plants of the nodes drawn as canopy
#define CLUSTER_STAT_COUNT 4

// Descriptor bindings of the cluster pass (its own set 0).
#define CLUSTER_BINDING_UNIFORMS 0   // ClusterUniforms
#define CLUSTER_BINDING_NODES 1      // ClusterNode[]
#define CLUSTER_BINDING_LEAF_STATE 2 // uint per leaf: 1 when it was near last frame
#define CLUSTER_BINDING_NEAR 3       // near chunks: header, then uvec2 (first plant, count | restart)
#define CLUSTER_BINDING_FAR 4        // uint far node indices
#define CLUSTER_BINDING_FAR_DRAW 5   // DrawCommand of the canopy: instanceCount = far nodes
#define CLUSTER_BINDING_STATS 6      // uint[CLUSTER_STAT_COUNT]

#define CLUSTER_ROOT_PARENT_PIXELS 3.0e38 // the root's parent is never fine enough to be far

// The canopy shell, a node's far representation (docs/CLUSTERS.md): per node
// CLUSTER_GRID² cells of canopy top height and albedo, baked at load
// (canopy_splat.comp, canopy_reduce.comp, canopy_resolve.comp), drawn as a
// displaced grid with skirts (canopy.vert, canopy_mesh.h).
#define CANOPY_CELLS (CLUSTER_GRID * CLUSTER_GRID)
#define CANOPY_BAKE_WORDS 5 // per cell while baking: height key (canopyHeightKey), plants, red, green, blue sums (×255)
#define CANOPY_EMPTY_SINK 2.0 // metres below the ground the shell sinks where a cell has no canopy

// One cell of a node's canopy as the draw reads it (uint texel).
struct CanopyCell {
    uint height; // float bits: the canopy top (m), or the ground minus CANOPY_EMPTY_SINK where empty
    uint ground; // float bits: the terrain at the cell's centre (m)
    uint albedo; // packUnorm4x8: linear albedo, a = 1 where the cell has canopy
    uint zero;
};

// Push constants of the bake passes.
struct CanopyBakePush {
    uvec4 range; // x first node, y nodes, z atlas frames per model, w 0
    vec4 params; // x the cluster threshold (canopy cell pixels), y crown radius fraction, zw 0
};

// Descriptor bindings of the canopy bake (its own set 0).
#define CANOPY_BAKE_BINDING_NODES 0     // ClusterNode[]
#define CANOPY_BAKE_BINDING_INSTANCES 1 // FieldInstance[]
#define CANOPY_BAKE_BINDING_MODELS 2    // PlantModel[]
#define CANOPY_BAKE_BINDING_ATLAS 3     // sampler2DArray: the impostor atlas's albedo + coverage
#define CANOPY_BAKE_BINDING_CELLS 4     // uint[CANOPY_BAKE_WORDS] per node cell, zeroed
#define CANOPY_BAKE_BINDING_GROUND 5    // float per node cell: the drawn terrain at its centre
#define CANOPY_BAKE_BINDING_CANOPY 6    // CanopyCell per node cell (the draw's)

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::ClusterNode) == CLUSTER_NODE_TEXELS * 16);
static_assert(sizeof(gpu::ClusterUniforms) == 10 * 16);
static_assert(sizeof(gpu::CanopyCell) == 16);
static_assert(sizeof(gpu::CanopyBakePush) == 32);
static_assert(CLUSTER_GRID % 2 == 0, "a parent's cell is four of one child's");
#endif

#endif
