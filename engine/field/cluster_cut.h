// The cut through the field's clusters (docs/CLUSTERS.md) on the CPU: the
// uniforms the cluster pass (cluster_pass.h) picks it with, for the camera's
// frustum or a box of the sun's, and clusterCutOnCpu, the same decision per
// node (shaders/shared/cluster_select.h), the reference the tests check the pass
// against. CPU only.
#pragma once

#include "shaders/shared/cluster_layouts.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace pf {

// Frustum (or the sun's box) planes, camera, cut and threshold; counts.x/y and
// limits are filled from the pass by setClusterUniforms.
gpu::ClusterUniforms makeClusterUniforms(const std::array<glm::vec4, 6>& planes, const glm::vec4& camera, uint32_t cut,
                                         float thresholdPixels, bool firstFrame);

// Whether some leaf can be far this frame, so the colour pass records the
// canopy's draw: every node forced far (CLUSTER_CUT_ALL_FAR), or with the
// automatic cut a leaf's cell below `thresholdPixels` at the field's
// farthest point from `camera` (xyz, w pixels per metre at one metre) —
// most views of a small field have no far node. `nodes` leaves first, the
// root last (ClusterTree::nodes).
bool canopyCanBeDrawn(std::span<const gpu::ClusterNode> nodes, const glm::vec4& camera, uint32_t cut,
                      float thresholdPixels);

// The cluster pass's cut on the CPU: decision per node, the far nodes and near leaves sorted.
struct CpuClusterCut {
    std::vector<uint32_t> decisions; // CLUSTER_CULLED, _COVERED, _FAR, _NEAR per node
    std::vector<uint32_t> far, near;
};
CpuClusterCut clusterCutOnCpu(std::span<const gpu::ClusterNode> nodes, uint32_t leafCount,
                              const gpu::ClusterUniforms& uniforms);

} // namespace pf
