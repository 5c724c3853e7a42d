#version 460
#extension GL_GOOGLE_include_directive : require
#include "cluster_layouts.h"
#include "lod_select.h"

// Cull + LOD (docs/CULLING.md): one invocation per near plant. Frustum
// test of the instance's bounding sphere, LOD from its projected height with
// hysteresis, and one append per LOD list it is drawn in this frame (two
// while it cross-fades between LODs).
layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CULL_BINDING_UNIFORMS, std140) uniform CullBlock {
    CullUniforms cull;
};
layout(set = 0, binding = CULL_BINDING_INSTANCES, std430) readonly buffer Instances {
    FieldInstance instances[];
};
layout(set = 0, binding = CULL_BINDING_MODELS, std430) readonly buffer Models {
    PlantModel models[];
};
layout(set = 0, binding = CULL_BINDING_STATE, std430) buffer State {
    uint state[];
};
layout(set = 0, binding = CULL_BINDING_COUNTS, std430) buffer Counts {
    uint counts[];
};
layout(set = 0, binding = CULL_BINDING_VISIBLE, std430) writeonly buffer Visible {
    uint visible[];
};

void append(uint modelIndex, PlantModel model, uint lod, uint entry) {
    uint slot = atomicAdd(counts[modelIndex * LOD_COUNT + lod], 1u);
    visible[model.lists[lod] + slot] = entry;
}

#include "near_chunks.glsl"

void main() {
    uint index;
    bool restart;
    if (!nearPlant(index, restart)) return;

    FieldInstance inst = instances[index];
    uint modelIndex = inst.ids.x;
    PlantModel model = models[modelIndex];
    vec4 sphere = instanceSphere(inst, model);
    bool inside = sphereInFrustum(sphere, cull.frustum[0], cull.frustum[1], cull.frustum[2], cull.frustum[3],
                                  cull.frustum[4], cull.frustum[5]);
    float pixels = projectedPixels(sphere, cull.camera);
    inside = inside && largeEnoughToDraw(pixels, model, cull.counts.z);
    uint next = nextLodState(state[index], inside, pixels, model.lod, cull.counts.z, cull.counts.w == 1u || restart,
                             cull.timing.x);
    state[index] = next;
    if (!inside) return;

    uint progress = lodStateProgress(next);
    if (progress == LOD_STATE_SETTLED) {
        append(modelIndex, model, lodStateCurrent(next), visibleEntry(index, 0u, VISIBLE_COVERAGE_MAX));
        return;
    }
    uint coverageIn = fadeInCoverage(progress);
    append(modelIndex, model, lodStateCurrent(next), visibleEntry(index, VISIBLE_FADE_IN_BIT, coverageIn));
    append(modelIndex, model, lodStateFrom(next), visibleEntry(index, 0u, VISIBLE_COVERAGE_MAX - coverageIn));
}
