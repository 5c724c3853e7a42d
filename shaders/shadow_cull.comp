#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/cluster_layouts.h"
#include "shared/shadow_select.h"

// The sun's shadow casters (shadow_select.h): one invocation per plant of
// the leaves meeting the sun's box (near_chunks.glsl) appends it, at full
// coverage, to the visible list of the LOD it casts from in this pass, the
// cache's or the frame's (counts.w). The
// layout is the cull pass's (CULL_BINDING_*), without the LOD state, so
// build_draws.comp turns the lists into indirect draws as it does for the
// camera's.
layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CULL_BINDING_UNIFORMS, std430) readonly buffer ShadowCullBlock {
    ShadowCullUniforms cull;
};
layout(set = 0, binding = CULL_BINDING_INSTANCES, std430) readonly buffer Instances {
    FieldInstance instances[];
};
layout(set = 0, binding = CULL_BINDING_MODELS, std430) readonly buffer Models {
    PlantModel models[];
};
layout(set = 0, binding = CULL_BINDING_COUNTS, std430) buffer Counts {
    uint counts[];
};
layout(set = 0, binding = CULL_BINDING_VISIBLE, std430) writeonly buffer Visible {
    uint visible[];
};

#include "near_chunks.glsl"

void main() {
    uint index;
    bool restart; // the casters keep no LOD state
    if (!nearPlant(index, restart)) return;

    FieldInstance inst = instances[index];
    uint modelIndex = inst.ids.x;
    PlantModel model = models[modelIndex];
    uint lod = shadowCasterLod(inst, model, cull);
    if (lod == SHADOW_NOT_CAST) return;
    uint slot = atomicAdd(counts[modelIndex * LOD_COUNT + lod], 1u);
    visible[model.lists[lod] + slot] = visibleEntry(index, 0u, VISIBLE_COVERAGE_MAX);
}
