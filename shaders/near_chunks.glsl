// The per-plant passes (cull.comp, shadow_cull.comp) run over the near
// chunks of the cluster pass (cluster_layouts.h), or over every plant in
// chunks the cull pass wrote once at creation: one workgroup per chunk of at
// most CULL_GROUP_SIZE plants, in rows past maxComputeWorkGroupCount[0].
layout(set = 0, binding = CULL_BINDING_NEAR, std430) readonly buffer NearChunks {
    uint nearChunkCount;
    uint nearDispatch[3];
    uvec2 nearChunks[];
};

// The plant of this invocation (false: none), and whether its leaf just
// turned near (its LOD state starts settled, as on a first frame).
bool nearPlant(out uint index, out bool restart) {
    uint chunkIndex = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (chunkIndex >= nearChunkCount) return false;
    uvec2 chunk = nearChunks[chunkIndex];
    index = chunk.x + gl_LocalInvocationID.x;
    restart = (chunk.y & NEAR_CHUNK_RESTART_BIT) != 0u;
    return gl_LocalInvocationID.x < (chunk.y & NEAR_CHUNK_COUNT_MASK);
}
