// The canopy shell, the far representation of a cluster (docs/CLUSTERS.md):
// per node of the quadtree CLUSTER_GRID² cells of canopy top and albedo,
// baked on the GPU at load from the plants' impostor boxes and atlas
// colours (leaves splatted, inner nodes reduced from their children), and
// the mesh every far node is drawn with (shaders/shared/canopy_mesh.h).
#pragma once

#include "engine/field/impostor_atlas.h"
#include "engine/scene/clusters.h"
#include "engine/scene/terrain.h"
#include "engine/vk/resources.h"

#include <vector>

namespace pf {

struct CanopyBakeInputs {
    const ClusterTree* tree = nullptr;
    const Buffer* nodes = nullptr;     // tree->nodes, storage
    const Buffer* instances = nullptr; // FieldInstance[], storage, in cluster order
    const Buffer* models = nullptr;    // PlantModel[], storage, impostors baked
    const ImpostorAtlas* atlas = nullptr;
    const Heightfield* ground = nullptr; // the terrain as drawn
    float thresholdPixels = 1.0f;        // ClusterSettings::thresholdPixels: plants hidden at it are left out
    float crownRadius = 0.8f;            // of the impostor box's half width, the crown's
};

// CanopyCell per node cell (node after node, CANOPY_CELLS each), owned by
// `owner` and readable by vertex shaders through a uint texel view.
Buffer bakeCanopy(GpuResources& owner, const CanopyBakeInputs& inputs);

// The terrain at the centre of every node cell, in bakeCanopy's order.
std::vector<float> canopyGround(const ClusterTree& tree, const Heightfield& ground);

// Triangles of one node's mesh: the grid of cell centres, then the skirt
// (drawn last, and without culling, so the tops hide the far walls).
std::vector<uint32_t> canopyMeshIndices();

} // namespace pf
