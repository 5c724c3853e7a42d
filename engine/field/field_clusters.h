// The field's clusters (docs/CLUSTERS.md), made at load: the quadtree over
// the plants (in cluster order since buildFieldContent), its nodes on the
// GPU, every node's canopy baked (canopy.h) and the mesh one far node is
// drawn with. The cluster passes that cut through it each frame
// (cluster_pass.h) belong to the camera's cull and to the shadow passes.
#pragma once

#include "engine/field/field_geometry.h"
#include "engine/scene/clusters.h"
#include "engine/vk/resources.h"

namespace pf {

// The field's hierarchy of clusters (docs/CLUSTERS.md).
struct ClusterSettings {
    bool enabled = true;    // false: every plant through the per-plant cull every frame (--no-clusters)
    float leafSide = 32.0f; // metres: leaves are the largest quadtree tiles of the terrain no wider than this
    // A node is drawn as its canopy where one canopy cell covers fewer pixels than this and its parent's does not.
    float thresholdPixels = 1.0f;
};

struct FieldClusters {
    ClusterTree tree;
    Buffer nodes;               // tree.nodes, storage and texels
    Buffer canopy;              // CanopyCell per node cell (bakeCanopy)
    Buffer canopyIndices;       // the mesh of one far node (canopyMeshIndices)
    gpu::DrawCommand farMesh{}; // the canopy's draw without instances
};

// Owned by `owner`.
FieldClusters createFieldClusters(GpuResources& owner, const FieldContent& content, const FieldPlants& plants,
                                  const FieldPlantBuffers& buffers, const FieldGeometry& geometry,
                                  const ClusterSettings& settings);

} // namespace pf
