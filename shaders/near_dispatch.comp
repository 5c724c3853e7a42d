#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/cluster_layouts.h"

// One invocation after cluster.comp: the per-plant cull's indirect dispatch,
// one workgroup per near chunk, in rows of at most
// maxComputeWorkGroupCount[0] groups.
layout(local_size_x = 1) in;

layout(set = 0, binding = CLUSTER_BINDING_UNIFORMS, std430) readonly buffer ClusterBlock {
    ClusterUniforms cluster;
};
layout(set = 0, binding = CLUSTER_BINDING_NEAR, std430) buffer Near {
    uint nearChunkCount;
    uint nearDispatch[3];
};

void main() {
    uint n = nearChunkCount, row = cluster.limits.x;
    nearDispatch[0] = min(n, row);
    nearDispatch[1] = (n + row - 1u) / row;
    nearDispatch[2] = 1u;
}
