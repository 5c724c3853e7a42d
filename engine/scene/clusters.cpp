#include "engine/scene/clusters.h"

#include "shaders/shared/lod_select.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pf {
namespace {

// Bits of v spread to the even positions (Morton interleave of 16-bit values).
uint32_t spreadBits(uint32_t v) {
    v &= 0xFFFFu;
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

uint32_t compactBits(uint32_t v) {
    v &= 0x55555555u;
    v = (v | (v >> 1)) & 0x33333333u;
    v = (v | (v >> 2)) & 0x0F0F0F0Fu;
    v = (v | (v >> 4)) & 0x00FF00FFu;
    v = (v | (v >> 8)) & 0x0000FFFFu;
    return v;
}

gpu::ClusterNode emptyNode(const ClusterSquare& root, uint32_t code, uint32_t depth, uint32_t level) {
    gpu::ClusterNode node{};
    const float side = root.side / float(1u << depth);
    node.square = glm::vec4(root.min.x + float(compactBits(code)) * side,
                            root.min.y + float(compactBits(code >> 1)) * side, side, side / float(CLUSTER_GRID));
    node.boxMin = glm::vec4(std::numeric_limits<float>::max());
    node.boxMax = glm::vec4(std::numeric_limits<float>::lowest());
    node.boxMin.w = node.boxMax.w = 0.0f;
    node.range = glm::uvec4(0, 0, CLUSTER_NONE, level);
    node.children = glm::uvec4(CLUSTER_NONE);
    return node;
}

void growBox(gpu::ClusterNode& node, glm::vec3 lo, glm::vec3 hi) {
    node.boxMin = glm::vec4(glm::min(glm::vec3(node.boxMin), lo), 0.0f);
    node.boxMax = glm::vec4(glm::max(glm::vec3(node.boxMax), hi), 0.0f);
}

} // namespace

ClusterSquare clusterRoot(const Heightfield& terrain) { return {glm::vec2(-0.5f * terrain.size), terrain.size}; }

uint32_t clusterOrderKey(const ClusterSquare& root, glm::vec2 xz) {
    const float tiles = float(1u << kClusterOrderDepth);
    auto tile = [&](float v, float min) {
        const float t = std::floor((v - min) / root.side * tiles);
        return uint32_t(std::clamp(t, 0.0f, tiles - 1.0f));
    };
    return spreadBits(tile(xz.x, root.min.x)) | (spreadBits(tile(xz.y, root.min.y)) << 1);
}

void sortPlantsByCluster(std::vector<PlantInstance>& plants, const ClusterSquare& root) {
    std::vector<std::pair<uint32_t, uint32_t>> keys(plants.size());
    for (uint32_t i = 0; i < plants.size(); ++i)
        keys[i] = {clusterOrderKey(root, {plants[i].position.x, plants[i].position.z}), i};
    std::sort(keys.begin(), keys.end()); // ties broken by the old index: stable
    std::vector<PlantInstance> sorted;
    sorted.reserve(plants.size());
    for (const auto& key : keys) sorted.push_back(plants[key.second]);
    plants = std::move(sorted);
}

uint32_t clusterDepthFor(const ClusterSquare& root, float leafSide) {
    uint32_t depth = 0;
    while (depth < kClusterOrderDepth && root.side / float(1u << depth) > leafSide) ++depth;
    return depth;
}

ClusterTree buildClusterTree(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                             const ClusterSquare& root, float leafSide) {
    ClusterTree tree;
    tree.depth = clusterDepthFor(root, leafSide);
    const uint32_t shift = 2 * (kClusterOrderDepth - tree.depth);

    // Leaves: runs of plants with the same tile code at the leaf depth.
    std::vector<uint32_t> codes; // of the nodes of the level being built
    uint32_t previousKey = 0;
    for (uint32_t i = 0; i < instances.size(); ++i) {
        const gpu::FieldInstance& inst = instances[i];
        const uint32_t key = clusterOrderKey(root, {inst.positionScale.x, inst.positionScale.z});
        if (i > 0 && key < previousKey) throw std::runtime_error("cluster tree: instances are not in cluster order");
        previousKey = key;
        const uint32_t code = uint32_t(uint64_t(key) >> shift); // a shift by 32 (one leaf, the root) gives 0
        if (codes.empty() || codes.back() != code) {
            codes.push_back(code);
            tree.nodes.push_back(emptyNode(root, code, tree.depth, 0));
            tree.nodes.back().range.x = i;
        }
        gpu::ClusterNode& leaf = tree.nodes.back();
        ++leaf.range.y;
        const glm::vec4 sphere = gpu::instanceSphere(inst, models[inst.ids.x]);
        growBox(leaf, glm::vec3(sphere) - sphere.w, glm::vec3(sphere) + sphere.w);
    }
    tree.levelStart = {0, uint32_t(tree.nodes.size())};
    if (tree.nodes.empty()) return tree;

    // Each level up: consecutive nodes with the same parent code (Morton order
    // keeps siblings together) make one parent.
    for (uint32_t level = 1, depth = tree.depth; depth > 0; ++level) {
        --depth;
        const uint32_t first = tree.levelStart[level - 1], end = tree.levelStart[level];
        std::vector<uint32_t> parentCodes;
        for (uint32_t n = first; n < end; ++n) {
            const uint32_t code = codes[n - first] >> 2;
            if (parentCodes.empty() || parentCodes.back() != code) {
                parentCodes.push_back(code);
                tree.nodes.push_back(emptyNode(root, code, depth, level));
                tree.nodes.back().range.x = tree.nodes[n].range.x;
            }
            const uint32_t parentIndex = uint32_t(tree.nodes.size()) - 1;
            gpu::ClusterNode& parent = tree.nodes.back();
            gpu::ClusterNode& child = tree.nodes[n];
            child.range.z = parentIndex;
            parent.children[codes[n - first] & 3u] = n;
            parent.range.y += child.range.y;
            growBox(parent, glm::vec3(child.boxMin), glm::vec3(child.boxMax));
        }
        codes = std::move(parentCodes);
        tree.levelStart.push_back(uint32_t(tree.nodes.size()));
    }
    return tree;
}

} // namespace pf
