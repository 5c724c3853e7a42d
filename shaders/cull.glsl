// Cull + LOD (docs/CULLING.md): one invocation per near plant. Frustum
// test of the instance's bounding sphere, LOD from its projected height with
// hysteresis, and one append per LOD list it is drawn in this frame (two
// while it cross-fades between LODs). Included by cull.comp (the phases
// CULL_PHASE_ALL and CULL_PHASE_EARLY) and, with CULL_LATE, by
// cull_late.comp (CULL_PHASE_LATE: the occlusion test against the depth
// pyramid, and every plant's visible bit).
#include "shared/cluster_layouts.h"
#include "shared/lod_select.h"
#ifdef CULL_LATE
#include "shared/depth_pyramid_layouts.h"
#include "shared/occlusion_test.h"
#endif

layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CULL_BINDING_UNIFORMS, std430) readonly buffer CullBlock {
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
// Region 0 (phases ALL and EARLY), region 1 (LATE), then the late phase's
// count of plants the pyramid hid.
layout(set = 0, binding = CULL_BINDING_COUNTS, std430) buffer Counts {
    uint counts[];
};
layout(set = 0, binding = CULL_BINDING_VISIBLE, std430) writeonly buffer Visible {
    uint visible[];
};
layout(push_constant) uniform Push {
    CullPush push;
};
#ifdef CULL_LATE
layout(set = CULL_SET_PYRAMID, binding = DEPTH_PYRAMID_BINDING) uniform sampler2D pyramid;

// False when the pyramid shows the sphere hidden behind what the early phase drew.
bool mayBeVisible(vec4 sphere) {
    vec4 viewSphere = vec4((cull.view * vec4(sphere.xyz, 1.0)).xyz, sphere.w);
    if (sphereNearCamera(viewSphere, cull.viewport.z)) return true;
    uvec4 pixels = rectPixels(sphereScreenRect(viewSphere, cull.projection), cull.viewport.xy);
    uint level = pyramidLevel(pixels, uint(cull.viewport.w));
    uvec4 t = pixels >> (level + 1u);
    int l = int(level);
    float farthest = max(max(texelFetch(pyramid, ivec2(t.xy), l).r, texelFetch(pyramid, ivec2(t.zy), l).r),
                         max(texelFetch(pyramid, ivec2(t.xw), l).r, texelFetch(pyramid, ivec2(t.zw), l).r));
    return sphereNearestDepth(viewSphere, cull.projection) <= farthest;
}
#endif

// Appends to this phase's part of the (model, LOD) list: the late phase's
// entries follow the early phase's.
void append(uint modelIndex, PlantModel model, uint lod, uint entry) {
    uint counter = modelIndex * LOD_COUNT + lod;
    uint first = model.lists[lod];
#ifdef CULL_LATE
    first += counts[counter];
    counter += push.phase.y;
#endif
    uint slot = atomicAdd(counts[counter], 1u);
    visible[first + slot] = entry;
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
    // A plant whose leaf just turned near starts as on a first frame: its
    // state and visible bit are from when it was last near.
    bool firstFrame = cull.counts.w == 1u || restart;
    uint previous = state[index];
    // The early phase draws the plants drawn last frame that are still in
    // view (none on a first frame), and only it moves their LOD state on.
    bool drawnEarly = !firstFrame && (previous & LOD_STATE_VISIBLE_BIT) != 0u && inside;
#ifdef CULL_LATE
    bool visibleNow = inside && mayBeVisible(sphere);
    if (inside && !visibleNow && !drawnEarly) atomicAdd(counts[2u * push.phase.y], 1u);
    if (drawnEarly) {
        state[index] = visibleNow ? previous : previous & ~LOD_STATE_VISIBLE_BIT;
        return;
    }
    inside = visibleNow;
    uint visibleBit = visibleNow ? LOD_STATE_VISIBLE_BIT : 0u;
#else
    if (push.phase.x == CULL_PHASE_EARLY && !drawnEarly) return;
    uint visibleBit = previous & LOD_STATE_VISIBLE_BIT; // the late phase reads and rewrites it
#endif
    uint next = nextLodState(previous, inside, pixels, model.lod, cull.counts.z, firstFrame, cull.timing.x);
    state[index] = next | visibleBit;
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
