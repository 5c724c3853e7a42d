// Bindings and helpers of the canopy bake passes (cluster_layouts.h): cells
// of every node, CANOPY_BAKE_WORDS each, node after node, row by row.
#include "shared/cluster_layouts.h"

layout(local_size_x = CULL_GROUP_SIZE) in;

layout(push_constant) uniform BakePush {
    CanopyBakePush bake;
};
layout(set = 0, binding = CANOPY_BAKE_BINDING_NODES, std430) readonly buffer Nodes {
    ClusterNode nodes[];
};
layout(set = 0, binding = CANOPY_BAKE_BINDING_CELLS, std430) buffer Cells {
    uint cells[];
};

uint bakeCell(uint node, uint i, uint j) {
    return ((node * uint(CLUSTER_GRID) + j) * uint(CLUSTER_GRID) + i) * uint(CANOPY_BAKE_WORDS);
}

// Heights as uints that order like the floats (atomicMax); 0 is below every height: no canopy.
uint canopyHeightKey(float h) {
    uint u = floatBitsToUint(h);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

float canopyHeight(uint key) {
    return uintBitsToFloat((key & 0x80000000u) != 0u ? key & 0x7FFFFFFFu : ~key);
}

// The invocation's index over rows of workgroups (dispatches past maxComputeWorkGroupCount[0]).
uint bakeInvocation() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * CULL_GROUP_SIZE + gl_LocalInvocationID.x;
}
