#include "engine/field/shadow_pass.h"

#include "engine/field/shadow_casters.h"
#include "engine/vk/pipeline.h"

#include "shaders/impostor_shadow_frag.spv.h"
#include "shaders/impostor_shadow_vert.spv.h"
#include "shaders/plant_shadow_frag.spv.h"
#include "shaders/plant_vert.spv.h"

#include <algorithm>

namespace pf {
namespace {

ShadowCasters createShadowCasters(GpuResources& owner, const ShadowPassInputs& inputs) {
    ShadowCasters c;
    if (inputs.clusters)
        c.clusters = createClusterPass(owner, inputs.clusters->tree, inputs.clusters->nodes, inputs.clusters->farMesh);
    CullPassInputs plants = inputs.plants;
    plants.kind = CullKind::ShadowCasters;
    plants.near = inputs.clusters ? &c.clusters.near : nullptr;
    c.casters = createCullPass(owner, plants);
    return c;
}

// Depth only, seen from the sun: both sides of everything cast shadows.
SurfacePipelines createShadowPipelines(GpuResources& owner, VkPipelineLayout layout) {
    GpuResources modules(owner.ctx());
    GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.depthFormat = kShadowFormat;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE; // an ordinary viewport (shadow_map.h)
    desc.depthBiasConstant = 1.5f;
    desc.depthBiasSlope = 2.0f;
    desc.cullMode = VK_CULL_MODE_NONE;
    SurfacePipelines p;
    p.pass = FIELD_PASS_SHADOW;
    desc.vertex = createShaderModule(modules, spirv_plant_vert);
    desc.fragment = createShaderModule(modules, spirv_plant_shadow_frag);
    p.bark = p.foliage = createGraphicsPipeline(owner, desc);
    desc.vertex = createShaderModule(modules, spirv_impostor_shadow_vert);
    desc.fragment = createShaderModule(modules, spirv_impostor_shadow_frag);
    p.impostors[0] = {createGraphicsPipeline(owner, desc), IMPOSTOR_PART_NONE};
    return p;
}

// A caster pass's uniforms, and with clusters the leaves meeting its box.
void setCasterUniforms(const ShadowPass& pass, const ShadowCasters& casters, const gpu::ShadowCullUniforms& uniforms) {
    setCullUniforms(casters.casters, uniforms);
    if (!pass.clustered) return;
    std::array<glm::vec4, 6> box;
    std::copy(std::begin(uniforms.box), std::end(uniforms.box), box.begin());
    setClusterUniforms(casters.clusters, makeClusterUniforms(box, uniforms.camera, CLUSTER_CUT_BOX_ONLY, 0.0f, false));
}

void pickCasters(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowCasters& casters) {
    if (pass.clustered) recordClusterPass(cmd, casters.clusters);
    recordCullPass(cmd, casters.casters);
}

// The casters' lists: depth from the sun, into the frame's map or the cache (`fieldPass`).
void drawCasters(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowCasters& casters, uint32_t fieldPass,
                 const SurfaceGeometry& geometry) {
    bindDrawSet(cmd, geometry.layout, casters.set);
    pushFieldPass(cmd, geometry.layout, fieldPass);
    SurfaceLists lists;
    lists.plants = &casters.casters;
    recordSurfaceDraws(cmd, geometry, pass.pipelines, lists);
}

// The static casters, into the cache.
void recordShadowCache(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowMap& map,
                       const SurfaceGeometry& geometry) {
    pickCasters(cmd, pass, pass.cache);
    beginShadowCachePass(cmd, map);
    drawCasters(cmd, pass, pass.cache, FIELD_PASS_SHADOW_CACHE, geometry);
    endShadowCachePass(cmd, map);
}

} // namespace

ShadowPass createShadowPass(GpuResources& owner, const ShadowPassInputs& inputs) {
    ShadowPass pass;
    pass.clustered = inputs.clusters != nullptr;
    pass.cacheSettings = inputs.cache;
    pass.cache = createShadowCasters(owner, inputs);
    pass.frame = createShadowCasters(owner, inputs);
    const Buffer* lists[] = {&pass.cache.casters.visible, &pass.frame.casters.visible};
    const std::vector<VkDescriptorSet> sets = createDrawSets(owner, *inputs.table, lists);
    pass.cache.set = sets[0];
    pass.frame.set = sets[1];
    pass.pipelines = createShadowPipelines(owner, inputs.table->layout);
    return pass;
}

void setShadowView(ShadowPass& pass, const ShadowMap& map, const ShadowView& frame, bool firstFrame,
                   const glm::mat4& cameraViewProj, gpu::FieldFrame& field) {
    const ShadowCacheSettings& cache = pass.cacheSettings;
    pass.drawCache =
        firstFrame || !cache.reuse || pass.cacheRenders == 0 || !shadowCacheServes(pass.cached, frame, cache);
    if (pass.drawCache) {
        pass.cached = shadowCacheFor(frame, (map.cacheSize - map.size) / 2);
        ++pass.cacheRenders;
    }
    field.sunCacheViewProj = sunViewProjection(pass.cached.square, kSunDepthRadius);
    if (pass.drawCache)
        setCasterUniforms(pass, pass.cache,
                          makeShadowCullUniforms(field.sunCacheViewProj, cameraViewProj, frame, pass.cached, cache,
                                                 SHADOW_CULL_CACHE));
    // The frame's square in the cache's depth range, so the cache's window
    // copies into it texel for texel.
    SunSquare square = frame.square;
    square.depth = pass.cached.square.depth;
    pass.window = square.origin - pass.cached.square.origin;
    field.sunViewProj = sunViewProjection(square, kSunDepthRadius);
    setCasterUniforms(
        pass, pass.frame,
        makeShadowCullUniforms(field.sunViewProj, cameraViewProj, frame, pass.cached, cache, SHADOW_CULL_FRAME));
}

void recordShadowPass(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowMap& map,
                      const SurfaceGeometry& geometry) {
    if (pass.drawCache) recordShadowCache(cmd, pass, map, geometry);
    pickCasters(cmd, pass, pass.frame);
    beginShadowPassFromCache(cmd, map, pass.window);
    drawCasters(cmd, pass, pass.frame, FIELD_PASS_SHADOW, geometry);
    endShadowPass(cmd, map);
}

void recordNaiveShadowPass(VkCommandBuffer cmd, const ShadowPass& pass, const ShadowMap& map,
                           const SurfaceGeometry& geometry, VkDescriptorSet naiveSet) {
    if (pass.drawCache) recordShadowCache(cmd, pass, map, geometry);
    bindDrawSet(cmd, geometry.layout, naiveSet);
    beginShadowPass(cmd, map);
    pushFieldPass(cmd, geometry.layout, FIELD_PASS_SHADOW);
    recordSurfaceDraws(cmd, geometry, pass.pipelines, SurfaceLists{});
    endShadowPass(cmd, map);
}

} // namespace pf
