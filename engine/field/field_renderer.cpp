#include "engine/field/field_renderer.h"

#include "engine/field/cluster_cut.h"
#include "engine/field/cull_uniforms.h"
#include "engine/field/draw_templates.h"
#include "engine/field/impostor_atlas_images.h"
#include "engine/field/impostor_sources.h"
#include "engine/field/visible_lists.h"
#include "engine/vk/gpu_timer.h"
#include "shaders/shared/lod_select.h"

#include <cstring>
#include <stdexcept>

namespace pf {
namespace {

// The frame block of field shaders: FrameUniforms, then FieldFrame (std140;
// FrameUniforms is a multiple of 16 bytes, so FieldFrame follows unpadded).
struct FieldUniformBlock {
    gpu::FrameUniforms frame;
    gpu::FieldFrame field;
};

} // namespace

FieldRenderer::FieldRenderer(const GpuContext& ctx, FieldContent content, const FieldRenderSettings& settings)
    : ctx_(ctx), content_(std::move(content)), fieldBox_(fieldBox(content_)), settings_(settings), resources_(ctx) {
    settings_.antialiasing = supportedAntialiasing(ctx_, settings.antialiasing);
    if (content_.plants.size() > FIELD_MAX_INSTANCES)
        throw DeviceLimitError("at most " + std::to_string(FIELD_MAX_INSTANCES) + " plants can be drawn");
    // The traced pass runs before the colour pass, over the plants the cull
    // lists then; occlusion culling adds plants between the colour pass's parts.
    const bool traced = settings_.shadows == SunShadows::raytraced;
    if (traced && settings_.occlusionCulling)
        throw std::runtime_error("ray-traced shadows and occlusion culling do not go together: the rays start from "
                                 "what a frame draws before its colour pass, and occlusion culling draws more in it");
    lsys::need(settings_.memory, "GPU uploads", fieldUploadBytes(content_));
    // More species than the impostor atlas holds are refused here, before any upload; the bake shares frames
    // between variants the same way.
    impostorSources(content_.models, impostorModelCapacity(ctx_, settings_.impostors));
    requireBindableVertexPool(ctx_, content_.models.vertices.size());
    uniforms_ = createHostBuffer(resources_, sizeof(FieldUniformBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    geometry_ = createFieldGeometry(resources_, content_, settings_.impostors);
    const FieldPlants plants = fieldPlantsOf(content_);
    plants_ = uploadFieldPlants(resources_, plants);
    if (clustered()) {
        clusters_ = createFieldClusters(resources_, content_, plants, plants_, geometry_, settings_.clusters);
        cameraClusters_ = createClusterPass(resources_, clusters_.tree, clusters_.nodes, clusters_.farMesh);
    }
    const std::vector<gpu::DrawTemplate> templates = drawTemplates(content_.models, geometry_.billboards);
    CullPassInputs lists;
    lists.instances = &plants_.instances;
    lists.models = &plants_.models;
    lists.instanceCount = uint32_t(plants.instances.size());
    lists.modelCount = uint32_t(plants.models.size());
    lists.templates = templates;
    lists.near = clustered() ? &cameraClusters_.near : nullptr;
    cull_ = createCullPass(resources_, lists);
    raytracedSun_ = traced ? createRaytracedSunPass(resources_, content_, plants.instances, settings_.memory)
                           : createRaytracedSunPlaceholder(resources_);
    motion_ = createFieldMotion(resources_, content_);
    const float texel = 2.0f * settings_.shadowRadius / float(settings_.shadowMapSize);
    shadowMap_ = createShadowMap(resources_, settings_.shadowMapSize, shadowCacheMargin(settings_.shadowCache, texel));

    drawTable_ = createDrawTable(resources_, {&uniforms_, &geometry_, &plants_, &shadowMap_, &motion_,
                                              clustered() ? &clusters_ : nullptr, &cameraClusters_, &raytracedSun_});
    color_ = createColorPass(resources_, {&drawTable_, &cull_.visible, &plants_.naiveVisible, &uniforms_,
                                          &geometry_.terrainVertices, &content_.scene, settings_.antialiasing});
    shadows_ =
        createShadowPass(resources_, {&drawTable_, lists, clustered() ? &clusters_ : nullptr, settings_.shadowCache});
    if (traced) raytracedOrigins_ = createRaytracedOriginsPass(resources_, drawTable_.layout);
}

FieldRenderer::~FieldRenderer() {
    // resources_ then destroys what the last frame used.
    vkDeviceWaitIdle(ctx_.device);
}

void replaceFieldContent(std::unique_ptr<FieldRenderer>& renderer, FieldContent content) {
    auto next = std::make_unique<FieldRenderer>(renderer->context(), std::move(content), renderer->settings());
    renderer = std::move(next);
}

// Every pass's uniforms for the frame: the frame block (camera, sun views,
// wind), the shadow passes' plan, the physics plan, the cull's and the
// camera's cut's, and what the colour pass draws.
void FieldRenderer::setView(const FieldView& view, VkExtent2D extent) {
    // From far away the scene's near plane would leave every depth rounded to the far plane.
    const Camera camera = withDepthRangeFor(view.camera, fieldBox_);
    const Environment env = environmentOf(content_.scene);
    const glm::vec3 sun = sunDirection(env);
    const glm::uvec2 viewport(extent.width, extent.height);
    FieldUniformBlock block{};
    block.frame = makeFrameUniforms(camera, env, viewport, view.time);
    const glm::mat4& viewProj = block.frame.viewProj;
    if (settings_.shadows != SunShadows::none) {
        const ShadowView frame = shadowViewAhead(camera, sun, settings_.shadowRadius, shadowMap_.size, extent.height,
                                                 view.forcedLod.value_or(LOD_NOT_FORCED));
        // Ray-traced shadows use the square only to choose the terrain chunks
        // whose pixels trace (visibleTerrainRanges): no map, no casters.
        if (settings_.shadows == SunShadows::raytraced)
            block.field.sunViewProj = sunViewProjection(frame.square, kSunDepthRadius);
        else
            setShadowView(shadows_, shadowMap_, frame, view.firstFrame, viewProj, block.field);
    }
    const float shadowTexel = 2.0f * settings_.shadowRadius / float(shadowMap_.size);
    block.field.viewport = glm::vec4(float(extent.width), float(extent.height), shadowTexel,
                                     settings_.shadows == SunShadows::none  ? FIELD_SUN_UNSHADOWED
                                     : settings_.shadows == SunShadows::map ? FIELD_SUN_SHADOW_MAP
                                                                            : FIELD_SUN_RAYTRACED);
    // The colour pass's sets sample the visibility of the frame's size.
    if (settings_.shadows == SunShadows::raytraced && resizeRaytracedSunImages(ctx_, raytracedSun_, extent)) {
        const VkDescriptorSet sets[] = {color_.listsSet, color_.naiveSet, shadows_.cache.set, shadows_.frame.set};
        writeRaytracedSunVisibility(ctx_, sets, raytracedSun_);
    }
    advanceFieldMotion(motion_, view.time, view.firstFrame, camera.position, view.realTime);
    // The physics pass's wind field, for the shaders that sway without a skeleton.
    const gpu::PhysicsUniforms wind =
        makePhysicsUniforms(motion_.wind, motion_.settings, view.time, motion_.settings.subStep, 0, 0, 0);
    block.field.wind = glm::vec4(wind.wind.x, wind.wind.y, wind.wind.z, view.time);
    block.field.windDetail = glm::vec4(wind.windDetail.x, wind.windDetail.y, wind.wind.w, settings_.impostorSway);
    std::memcpy(uniforms_.mapped, &block, sizeof(block));

    const gpu::CullUniforms cull = cameraCullUniforms(viewProj, camera, viewport, view.deltaTime, view.firstFrame,
                                                      view.forcedLod.value_or(LOD_NOT_FORCED));
    setCullUniforms(cull_, cull);
    const uint32_t cut = view.forcedCut.value_or(CLUSTER_CUT_AUTO);
    const float threshold = settings_.clusters.thresholdPixels;
    if (clustered())
        setClusterUniforms(cameraClusters_,
                           makeClusterUniforms(frustumPlanes(viewProj), cull.camera, cut, threshold, view.firstFrame));

    ColorView color;
    color.viewProj = viewProj;
    color.camera = camera.position;
    color.forward = glm::normalize(camera.target - camera.position);
    color.pixelsPerMetre = cull.camera.w;
    color.time = view.time;
    if (settings_.shadows != SunShadows::none) color.sunViewProj = block.field.sunViewProj;
    color.shadowTexel = shadowTexel;
    color.canopy = clustered() && canopyCanBeDrawn(clusters_.tree.nodes, cull.camera, cut, threshold);
    setColorView(color_, content_.scene, geometry_.terrainChunks, color);
}

SurfaceGeometry FieldRenderer::surfaceGeometry() const {
    return {&ctx_,    drawTable_.layout, &geometry_.indices, &geometry_.terrainIndices, &clusters_.canopyIndices,
            &content_};
}

void FieldRenderer::recordColor(VkCommandBuffer cmd, const RenderTarget& target, bool naive, GpuTimer* timer) const {
    const SurfaceGeometry geometry = surfaceGeometry();
    const ColorPassFrame frame{&geometry, &cull_, clustered() ? &cameraClusters_ : nullptr, settings_.occlusionCulling,
                               naive};
    recordColorPass(cmd, color_, frame, target, timer);
}

// The sun's visibility for the colour pass: the shadow map's passes, or the
// traced sun's origins and trace; the naive baseline's from every plant.
void FieldRenderer::recordSunShadows(VkCommandBuffer cmd, bool naive) const {
    const SurfaceGeometry geometry = surfaceGeometry();
    if (settings_.shadows == SunShadows::map) {
        if (naive)
            recordNaiveShadowPass(cmd, shadows_, shadowMap_, geometry, color_.naiveSet);
        else
            recordShadowPass(cmd, shadows_, shadowMap_, geometry);
    }
    if (settings_.shadows == SunShadows::raytraced) {
        SurfaceLists lists;
        lists.plants = naive ? nullptr : &cull_;
        lists.terrain = &color_.terrain;
        recordRaytracedOriginsPass(cmd, raytracedOrigins_, raytracedSun_.images, geometry,
                                   naive ? color_.naiveSet : color_.listsSet, lists);
        recordRaytracedSun(cmd, raytracedSun_, sunDirection(environmentOf(content_.scene)));
    }
}

void FieldRenderer::record(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    recordFieldMotion(cmd, motion_, timer);
    {
        TimedFieldScope scope(cmd, timer, FieldScope::clusters);
        if (clustered()) recordClusterPass(cmd, cameraClusters_);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::cull);
        recordCullPass(cmd, cull_, settings_.occlusionCulling ? CULL_PHASE_EARLY : CULL_PHASE_ALL);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::shadow);
        recordSunShadows(cmd, false);
    }
    recordColor(cmd, target, false, timer);
}

void FieldRenderer::recordNaive(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    recordFieldMotion(cmd, motion_, timer);
    { TimedFieldScope scope(cmd, timer, FieldScope::clusters); }
    { TimedFieldScope scope(cmd, timer, FieldScope::cull); }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::shadow);
        recordSunShadows(cmd, true);
    }
    recordColor(cmd, target, true, timer);
}

FieldFrameStats FieldRenderer::readStats() const {
    const CullCounts counts = readCullCounts(cull_);
    FieldFrameStats stats;
    stats.instances = uint32_t(content_.plants.size());
    stats.plantsPerLod = counts.perLod;
    stats.draws = counts.drawsPerClass;
    stats.occluded = counts.occluded;
    if (settings_.shadows == SunShadows::map) {
        stats.shadowCastersPerLod = readCullCounts(shadows_.frame.casters).perLod;
        stats.shadowCacheCasters = readCullCounts(shadows_.cache.casters).perLod[LOD_IMPOSTOR];
        stats.shadowCacheRenders = shadows_.cacheRenders;
    }
    if (clustered()) {
        const std::array<uint32_t, CLUSTER_STAT_COUNT> cut = readClusterStats(cameraClusters_);
        stats.clustersFar = cut[CLUSTER_STAT_FAR];
        stats.clusterFarPlants = cut[CLUSTER_STAT_FAR_PLANTS];
        stats.nearLeaves = cut[CLUSTER_STAT_NEAR_LEAVES];
        stats.nearPlants = cut[CLUSTER_STAT_NEAR_PLANTS];
        stats.triangles += uint64_t(stats.clustersFar) * (cameraClusters_.farMesh.indexCount / 3);
    }
    stats.triangles += plantTriangles(content_.models, counts.perModelLod);
    return stats;
}

VkDeviceSize FieldRenderer::gpuBytes() const { return resources_.bytes() + raytracedSun_.images.resources->bytes(); }

} // namespace pf
