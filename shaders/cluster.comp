#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/cluster_select.h"

// The cut through the field's quadtree (cluster_select.h): one invocation
// per node. Far nodes are appended to the canopy's instanced draw; near
// leaves are split into chunks of at most CULL_GROUP_SIZE plants, one cull
// workgroup each, so the per-plant cull runs over the plants near the camera
// only.
layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CLUSTER_BINDING_UNIFORMS, std430) readonly buffer ClusterBlock {
    ClusterUniforms cluster;
};
layout(set = 0, binding = CLUSTER_BINDING_NODES, std430) readonly buffer Nodes {
    ClusterNode nodes[];
};
layout(set = 0, binding = CLUSTER_BINDING_LEAF_STATE, std430) buffer LeafState {
    uint leafWasNear[];
};
layout(set = 0, binding = CLUSTER_BINDING_NEAR, std430) buffer Near {
    uint nearChunkCount;
    uint nearDispatch[3];
    uvec2 nearChunks[];
};
layout(set = 0, binding = CLUSTER_BINDING_FAR, std430) writeonly buffer Far {
    uint farNodes[];
};
layout(set = 0, binding = CLUSTER_BINDING_FAR_DRAW, std430) buffer FarDraw {
    DrawCommand farDraw;
};
layout(set = 0, binding = CLUSTER_BINDING_STATS, std430) buffer Stats {
    uint stats[CLUSTER_STAT_COUNT];
};

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= cluster.counts.x) return;

    ClusterNode node = nodes[index];
    uint parent = node.range.z;
    float parentPixels =
        parent == CLUSTER_NONE ? CLUSTER_ROOT_PARENT_PIXELS : clusterCellPixels(nodes[parent], cluster.camera);
    uint decision = clusterDecision(node, clusterCellPixels(node, cluster.camera), parentPixels,
                                    clusterInFrustum(node, cluster), cluster);
    if (decision == CLUSTER_FAR) {
        farNodes[atomicAdd(farDraw.instanceCount, 1u)] = index;
        atomicAdd(stats[CLUSTER_STAT_FAR], 1u);
        atomicAdd(stats[CLUSTER_STAT_FAR_PLANTS], node.range.y);
    }
    if (index >= cluster.counts.y) return;

    // A leaf: its plants' LOD state is stale unless it was near last frame.
    bool isNear = decision == CLUSTER_NEAR;
    uint restart = cluster.counts.w == 1u || leafWasNear[index] == 0u ? NEAR_CHUNK_RESTART_BIT : 0u;
    leafWasNear[index] = isNear ? 1u : 0u;
    if (!isNear) return;
    uint chunks = (node.range.y + CULL_GROUP_SIZE - 1u) / CULL_GROUP_SIZE;
    uint first = atomicAdd(nearChunkCount, chunks);
    for (uint c = 0u; c < chunks; ++c) {
        uint start = c * CULL_GROUP_SIZE;
        nearChunks[first + c] = uvec2(node.range.x + start, min(node.range.y - start, CULL_GROUP_SIZE) | restart);
    }
    atomicAdd(stats[CLUSTER_STAT_NEAR_LEAVES], 1u);
    atomicAdd(stats[CLUSTER_STAT_NEAR_PLANTS], node.range.y);
}
