// The FieldRenderer's sun shadows (docs/FIELD.md, "The sun's shadows"):
// whether the cache of static casters serves the frame, the shadow-caster
// passes that pick what the cache and the frame draw, and the passes that
// draw them into the cache and into the frame's map.
#include "engine/field/field_renderer.h"

#include "engine/field/shadow_casters.h"
#include "shaders/lod_select.h"

#include <algorithm>

namespace pf {
namespace {

// Metres the sun's box reaches either side of its depth.
constexpr float kShadowDepthRadius = 250.0f;

} // namespace

// The sun's square ahead of the camera and whether the cache of static
// casters serves it; sets both shadow-caster passes' uniforms and the
// view-projections of the frame's map and of the cache.
void FieldRenderer::planShadows(const FieldView& view, const glm::vec3& sun, VkExtent2D extent,
                                const glm::mat4& cameraViewProj, gpu::FieldFrame& field) {
    if (settings_.shadows == SunShadows::none) return;
    const glm::vec3 forward = glm::normalize(view.camera.target - view.camera.position);
    // Shadows where they are seen large: a square reaching ahead of the camera.
    const float radius = settings_.shadowRadius;
    const glm::vec3 flatForward = glm::length(glm::vec2(forward.x, forward.z)) > 1e-3f
                                      ? glm::normalize(glm::vec3(forward.x, 0.0f, forward.z))
                                      : glm::vec3(0.0f);
    const glm::vec3 focus = view.camera.position + flatForward * (0.6f * radius);
    ShadowView frame;
    frame.square = sunSquareAround(sun, focus, radius, shadow_.size);
    frame.sunDirection = sun;
    frame.camera = view.camera.position;
    frame.pixelsPerMetre = pixelsPerMetre(glm::radians(view.camera.fovYDegrees), extent.height);
    frame.forcedLod = view.forcedLod.value_or(LOD_NOT_FORCED);
    // Ray-traced shadows use the square only to choose the terrain chunks
    // whose pixels trace (visibleTerrainRanges): no map, no casters.
    if (settings_.shadows == SunShadows::traced) {
        field.sunViewProj = sunViewProjection(frame.square, kShadowDepthRadius);
        return;
    }

    // A first frame draws the cache for its own camera, so a capture does not
    // depend on the frames before it.
    const ShadowCacheSettings& cache = settings_.shadowCache;
    drawShadowCache_ =
        view.firstFrame || !cache.reuse || shadowCacheRenders_ == 0 || !shadowCacheServes(shadowCache_, frame, cache);
    if (drawShadowCache_) {
        shadowCache_ = shadowCacheFor(frame, (shadow_.cacheSize - shadow_.size) / 2);
        ++shadowCacheRenders_;
    }
    field.sunCacheViewProj = sunViewProjection(shadowCache_.square, kShadowDepthRadius);
    if (drawShadowCache_)
        setCasterUniforms(shadowCacheCasters_, shadowCacheClusters_,
                          makeShadowCullUniforms(field.sunCacheViewProj, cameraViewProj, frame, shadowCache_, cache,
                                                 SHADOW_CULL_CACHE));
    // The frame's square in the cache's depth range, so the cache's window
    // copies into it texel for texel.
    SunSquare square = frame.square;
    square.depth = shadowCache_.square.depth;
    shadowWindow_ = square.origin - shadowCache_.square.origin;
    field.sunViewProj = sunViewProjection(square, kShadowDepthRadius);
    setCasterUniforms(
        shadowFrameCasters_, shadowFrameClusters_,
        makeShadowCullUniforms(field.sunViewProj, cameraViewProj, frame, shadowCache_, cache, SHADOW_CULL_FRAME));
}

// A caster pass's uniforms, and with clusters the leaves meeting its box.
void FieldRenderer::setCasterUniforms(const CullPass& casters, const ClusterPass& clusters,
                                      const gpu::ShadowCullUniforms& uniforms) const {
    setCullUniforms(casters, uniforms);
    if (!settings_.clusters.enabled) return;
    std::array<glm::vec4, 6> box;
    std::copy(std::begin(uniforms.box), std::end(uniforms.box), box.begin());
    setClusterUniforms(clusters, makeClusterUniforms(box, uniforms.camera, CLUSTER_CUT_BOX_ONLY, 0.0f, false));
}

// Bark and foliage, then impostors, of the casters' lists: depth from the
// sun, into the frame's map or the cache (`pass`).
void FieldRenderer::drawShadowCasters(VkCommandBuffer cmd, const CullPass& casters, VkDescriptorSet set,
                                      uint32_t pass) const {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
    pushFieldPass(cmd, pass);
    vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.plantShadow);
    drawClassIndirect(cmd, ctx_, casters, DRAW_BARK);
    drawClassIndirect(cmd, ctx_, casters, DRAW_FOLIAGE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.impostorShadow);
    drawClassIndirect(cmd, ctx_, casters, DRAW_IMPOSTOR);
}

// The static casters, into the cache (when planShadows says so).
void FieldRenderer::recordShadowCache(VkCommandBuffer cmd) const {
    if (settings_.clusters.enabled) recordClusterPass(cmd, shadowCacheClusters_);
    recordCullPass(cmd, shadowCacheCasters_);
    beginShadowCachePass(cmd, shadow_);
    drawShadowCasters(cmd, shadowCacheCasters_, shadowCacheSet_, FIELD_PASS_SHADOW_CACHE);
    endShadowCachePass(cmd, shadow_);
}

// The frame's map: the cache's window, the frame's casters on top.
void FieldRenderer::recordShadowPass(VkCommandBuffer cmd) const {
    if (drawShadowCache_) recordShadowCache(cmd);
    if (settings_.clusters.enabled) recordClusterPass(cmd, shadowFrameClusters_);
    recordCullPass(cmd, shadowFrameCasters_);
    beginShadowPassFromCache(cmd, shadow_, shadowWindow_);
    drawShadowCasters(cmd, shadowFrameCasters_, shadowFrameSet_, FIELD_PASS_SHADOW);
    endShadowPass(cmd, shadow_);
}

// The baseline draws every plant at full detail into the map, no cache.
void FieldRenderer::recordNaiveShadowPass(VkCommandBuffer cmd) const {
    // A cache this frame was planned to draw is drawn all the same, so the
    // next record() finds it holding what planShadows says.
    if (drawShadowCache_) recordShadowCache(cmd);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &naiveSet_, 0, nullptr);
    beginShadowPass(cmd, shadow_);
    pushFieldPass(cmd, FIELD_PASS_SHADOW);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.plantShadow);
    vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    drawPlantsNaive(cmd, true, true);
    endShadowPass(cmd, shadow_);
}

} // namespace pf
