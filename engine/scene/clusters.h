// The field as a hierarchy of clusters (docs/CLUSTERS.md): a quadtree of
// square terrain tiles over the plants, built at load. Plants are kept in
// the Morton order of fine tiles of one root square, so every node of any
// quadtree over that square, whatever its leaf side, holds a contiguous range
// of plants. CPU only.
#pragma once

#include "engine/scene/placement.h"
#include "engine/scene/terrain.h"
#include "shaders/shared/cluster_layouts.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace pf {

// The square the quadtree subdivides.
struct ClusterSquare {
    glm::vec2 min{0.0f}; // x, z of its corner (m)
    float side = 1.0f;   // m
};

// The terrain's square.
ClusterSquare clusterRoot(const Heightfield& terrain);

// Depth of the finest tiles plants are ordered by: 2^16 a side.
inline constexpr uint32_t kClusterOrderDepth = 16;

// The Morton code of the finest tile holding (x, z); points outside the
// square fall into its edge tiles.
uint32_t clusterOrderKey(const ClusterSquare& root, glm::vec2 xz);

// Stable sort by clusterOrderKey: same plants ⇒ same order.
void sortPlantsByCluster(std::vector<PlantInstance>& plants, const ClusterSquare& root);

// The quadtree over instances sorted by sortPlantsByCluster (same root).
// Nodes are stored level by level from the leaves (level 0) to the root,
// each level in Morton order; only tiles holding plants are nodes.
struct ClusterTree {
    std::vector<gpu::ClusterNode> nodes;
    std::vector<uint32_t> levelStart; // level l's nodes are [levelStart[l], levelStart[l + 1]); the root is last
    uint32_t depth = 0;               // leaves are tiles of root.side / 2^depth
    uint32_t leafCount() const { return levelStart.size() > 1 ? levelStart[1] : 0; }
    uint32_t levels() const { return uint32_t(levelStart.size()) - 1; }
};

// Depth whose tiles are at most `leafSide` metres (at most kClusterOrderDepth).
uint32_t clusterDepthFor(const ClusterSquare& root, float leafSide);

// Bounds are the boxes of the instances' bounding spheres (gpu::instanceSphere
// of their models). Throws when the instances are not in cluster order.
ClusterTree buildClusterTree(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                             const ClusterSquare& root, float leafSide);

} // namespace pf
