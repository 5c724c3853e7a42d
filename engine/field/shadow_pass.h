// The sun's shadow map passes (docs/FIELD.md, "The sun's shadows"), the
// frame's "shadow" scope: when the cache of static casters does not serve
// the frame, the cache's cluster pass (the leaves in its box), its caster
// pass (shadow_casters.h) and its depth pass into the cache; then the
// frame's cluster and caster passes, the cache's window copied into the
// frame's map and the frame's casters drawn on top, all depth only from the
// sun through the casters' indirect draws (surface_draws.h). Reads the
// plants and the draw table, writes the shadow map (shadow_map.h) the
// colour pass samples.
#pragma once

#include "engine/field/cull_pass.h"
#include "engine/field/draw_sets.h"
#include "engine/field/field_clusters.h"
#include "engine/field/shadow_cache.h"
#include "engine/field/shadow_map.h"
#include "engine/field/surface_draws.h"

namespace pf {

// The casters of one map, the cache or the frame's.
struct ShadowCasters {
    ClusterPass clusters;                 // with clusters: the leaves meeting the map's box (CLUSTER_CUT_BOX_ONLY)
    CullPass casters;                     // CullKind::ShadowCasters, SHADOW_CULL_CACHE or _FRAME
    VkDescriptorSet set = VK_NULL_HANDLE; // the draw set with the casters' lists
};

struct ShadowPassInputs {
    const DrawTable* table = nullptr;
    CullPassInputs plants;                   // the plants, models and templates; the pass sets kind and near
    const FieldClusters* clusters = nullptr; // null without clusters: the casters pass over every plant
    ShadowCacheSettings cache;
};

struct ShadowPass {
    ShadowCasters cache, frame;
    SurfacePipelines pipelines; // depth only from the sun: one pipeline for bark and foliage, one for impostors
    bool clustered = false;
    ShadowCacheSettings cacheSettings;
    // setShadowView: what the cache holds, whether this frame draws it
    // again, where the frame's map starts in it, how often it was drawn.
    ShadowView cached;
    bool drawCache = false;
    glm::ivec2 window{0};
    uint64_t cacheRenders = 0;
};

// What the pass creates is owned by `owner`.
ShadowPass createShadowPass(GpuResources& owner, const ShadowPassInputs& inputs);

// Per frame, before record: whether the cache serves `frame` (the sun's
// square ahead of the camera, shadowViewAhead), both caster passes'
// uniforms for the camera's view-projection, and the view-projections of
// the frame's map and of the cache in `field`. A first frame draws the
// cache for its own camera, so a capture does not depend on the frames
// before it.
void setShadowView(ShadowPass& pass, const ShadowMap& map, const ShadowView& frame, bool firstFrame,
                   const glm::mat4& cameraViewProj, gpu::FieldFrame& field);

// The cache (when setShadowView says so), then the frame's map: the
// cache's window, the frame's casters on top.
void recordShadowPass(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowMap& map,
                      const SurfaceGeometry& geometry);
// The baseline: every plant at full detail into the map (`naiveSet`: the
// draw set of the naive list), no cache. A cache this frame was planned to
// draw is drawn all the same, so the next recordShadowPass finds it holding
// what setShadowView says.
void recordNaiveShadowPass(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowMap& map,
                           const SurfaceGeometry& geometry, VkDescriptorSet naiveSet);

} // namespace pf
