#include "engine/field/field_clusters.h"

#include "engine/field/canopy.h"

namespace pf {

FieldClusters createFieldClusters(GpuResources& owner, const FieldContent& content, const FieldPlants& plants,
                                  const FieldPlantBuffers& buffers, const FieldGeometry& geometry,
                                  const ClusterSettings& settings) {
    FieldClusters c;
    c.tree = buildClusterTree(plants.instances, plants.models, clusterRoot(content.terrain), settings.leafSide);
    c.nodes = uploadFieldVector(owner, c.tree.nodes, kStorageAndTexels);
    CanopyBakeInputs bake;
    bake.tree = &c.tree;
    bake.nodes = &c.nodes;
    bake.instances = &buffers.instances;
    bake.models = &buffers.models;
    bake.atlas = &geometry.atlas;
    bake.ground = &geometry.drawnTerrain;
    bake.thresholdPixels = settings.thresholdPixels;
    c.canopy = bakeCanopy(owner, bake);
    const std::vector<uint32_t> mesh = canopyMeshIndices();
    c.canopyIndices = uploadFieldVector(owner, mesh, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    c.farMesh.indexCount = uint32_t(mesh.size());
    return c;
}

} // namespace pf
