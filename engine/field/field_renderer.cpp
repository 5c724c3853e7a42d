#include "engine/field/field_renderer.h"

#include "engine/field/canopy.h"
#include "engine/field/field_uploads.h"
#include "engine/field/visible_lists.h"
#include "engine/scene/cloud_billboards.h"
#include "engine/vk/depth_pyramid.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/gpu_timer.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "shaders/lod_select.h"

#include "shaders/canopy_frag.spv.h"
#include "shaders/canopy_vert.spv.h"
#include "shaders/impostor_frag.spv.h"
#include "shaders/impostor_shadow_frag.spv.h"
#include "shaders/impostor_shadow_vert.spv.h"
#include "shaders/impostor_sunlit_frag.spv.h"
#include "shaders/impostor_vert.spv.h"
#include "shaders/plant_frag.spv.h"
#include "shaders/plant_shadow_frag.spv.h"
#include "shaders/plant_vert.spv.h"
#include "shaders/sky_frag.spv.h"
#include "shaders/sky_vert.spv.h"
#include "shaders/terrain_frag.spv.h"
#include "shaders/terrain_sunlit_frag.spv.h"
#include "shaders/terrain_vert.spv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
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

constexpr VkShaderStageFlags kDrawStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
// The draw shaders read their buffers through texel views (field_common.glsl);
// the cull pass reads instances and models, the impostor bake the vertices,
// as storage buffers.
constexpr VkBufferUsageFlags kStorageAndTexels =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

template <class T>
Buffer uploadVector(GpuResources& owner, const std::vector<T>& data, VkBufferUsageFlags usage) {
    if (data.empty()) throw std::runtime_error("field renderer: nothing to upload");
    return createDeviceBufferWithData(owner, data.data(), data.size() * sizeof(T), usage);
}

// The drawn terrain keeps at most this many samples a side: far cells of a
// finer grid are a pixel or two wide, and a CPU rasteriser pays per triangle.
constexpr uint32_t kTerrainDrawSamples = 129;
// Cells a side of the chunks a frame draws or leaves out (terrain_chunks.h):
// 64 chunks of 512 triangles for the most drawn samples.
constexpr uint32_t kTerrainChunkCells = 16;

// Every k-th sample (k the smallest step that fits), edges kept; a grid the
// step does not divide (a terrain grown to a plant count) is resampled
// bilinearly at maxSamples a side instead.
Heightfield decimated(const Heightfield& terrain, uint32_t maxSamples) {
    const uint32_t step = (terrain.resolution - 1 + maxSamples - 2) / (maxSamples - 1);
    if (step <= 1) return terrain;
    const bool whole = (terrain.resolution - 1) % step == 0;
    Heightfield coarse;
    coarse.resolution = whole ? (terrain.resolution - 1) / step + 1 : maxSamples;
    coarse.size = terrain.size;
    coarse.heights.reserve(size_t(coarse.resolution) * coarse.resolution);
    for (uint32_t z = 0; z < coarse.resolution; ++z)
        for (uint32_t x = 0; x < coarse.resolution; ++x)
            coarse.heights.push_back(whole ? terrain.height(x * step, z * step)
                                           : heightAt(terrain, coarse.coordinate(x), coarse.coordinate(z)));
    return coarse;
}

} // namespace

FieldRenderer::FieldRenderer(const GpuContext& ctx, FieldContent content, const FieldRenderSettings& settings)
    : ctx_(ctx), content_(std::move(content)), settings_(settings), resources_(ctx) {
    settings_.antialiasing = supportedAntialiasing(ctx_, settings.antialiasing);
    if (content_.plants.empty()) throw std::runtime_error("the scene places no plant");
    if (content_.plants.size() > FIELD_MAX_INSTANCES)
        throw std::runtime_error("at most " + std::to_string(FIELD_MAX_INSTANCES) + " plants can be drawn");
    // The traced pass runs before the colour pass, over the plants the cull
    // lists then; occlusion culling adds plants between the colour pass's parts.
    if (settings_.shadows == SunShadows::traced && settings_.occlusionCulling)
        throw std::runtime_error("ray-traced shadows and occlusion culling do not go together: the rays start from "
                                 "what a frame draws before its colour pass, and occlusion culling draws more in it");
    lsys::need(settings_.memory, "GPU uploads", fieldUploadBytes(content_));
    requireBindableVertexPool(ctx_, content_.models.vertices.size());
    uniforms_ = createHostBuffer(resources_, sizeof(FieldUniformBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    uploadGeometry();
    uploadInstances();
    motion_ = createFieldMotion(resources_, content_);
    const float texel = 2.0f * settings_.shadowRadius / float(settings_.shadowMapSize);
    shadow_ = createShadowMap(resources_, settings_.shadowMapSize, shadowCacheMargin(settings_.shadowCache, texel));
    createDescriptors();
    createPipelines();
    const auto samples = VkSampleCountFlagBits(colourPassSamples(settings_.antialiasing));
    clouds_ = createCloudPass(resources_, content_.scene.clouds, uniforms_, samples);
    cloudShadows_ =
        createCloudShadowPass(resources_, content_.scene.clouds, sunDirection(environmentOf(content_.scene)), uniforms_,
                              terrainVertices_, samples);
}

FieldRenderer::~FieldRenderer() {
    // resources_ then destroys what the last frame used.
    vkDeviceWaitIdle(ctx_.device);
}

void replaceFieldContent(std::unique_ptr<FieldRenderer>& renderer, FieldContent content) {
    auto next = std::make_unique<FieldRenderer>(renderer->context(), std::move(content), renderer->settings());
    renderer = std::move(next);
}

// Plant meshes and billboards in one vertex and one index pool, the
// impostors baked from them, and the terrain.
void FieldRenderer::uploadGeometry() {
    PlantModelPool& pool = content_.models;
    for (uint32_t quads = 1; quads <= 3; ++quads) billboards_[quads - 1] = appendBillboardMesh(pool, quads);
    vertices_ = uploadVector(resources_, pool.vertices, kStorageAndTexels);
    indices_ = uploadVector(resources_, pool.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    // The shadow frames are seen from the scene's sun, fixed per scene.
    const float sunElevation = std::asin(std::clamp(sunDirection(environmentOf(content_.scene)).y, -1.0f, 1.0f));
    atlas_ = bakeImpostorAtlas(resources_, pool, vertices_, indices_, sunElevation, settings_.impostors);
    outlines_ = uploadVector(resources_, atlas_.outlines, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);

    drawnTerrain_ = decimated(content_.terrain, kTerrainDrawSamples);
    const TerrainMesh mesh = makeTerrainMesh(drawnTerrain_);
    std::vector<gpu::TerrainVertex> terrain(mesh.positions.size());
    for (size_t i = 0; i < terrain.size(); ++i)
        terrain[i] = {glm::vec4(mesh.positions[i], 0.0f), glm::vec4(mesh.normals[i], 0.0f)};
    terrainVertices_ = uploadVector(resources_, terrain, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    terrainChunks_ = makeTerrainChunks(mesh, drawnTerrain_.resolution, kTerrainChunkCells);
    terrainIndices_ = uploadVector(resources_, terrainChunks_.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
}

// Instances, the models with their visible-list regions (assignVisibleLists),
// and the draw templates of the cull pass.
void FieldRenderer::uploadInstances() {
    PlantModelPool& pool = content_.models;
    const uint32_t plantCount = uint32_t(content_.plants.size());
    std::vector<gpu::FieldInstance> instances = fieldInstancesOf(content_);
    std::vector<gpu::PlantModel> models;
    for (const PlantModelInfo& info : pool.models) models.push_back(info.gpu);
    assignVisibleLists(models, instances);
    for (size_t m = 0; m < pool.models.size(); ++m) pool.models[m].gpu.lists = models[m].lists;
    models_ = uploadVector(resources_, models, kStorageAndTexels);
    instances_ = uploadVector(resources_, instances, kStorageAndTexels);
    if (settings_.clusters.enabled) createClusters(instances, models);

    std::vector<uint32_t> naive(plantCount);
    for (uint32_t i = 0; i < plantCount; ++i) naive[i] = i | (VISIBLE_COVERAGE_MAX << VISIBLE_COVERAGE_SHIFT);
    naiveVisible_ = uploadVector(resources_, naive, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);

    // Templates sorted by class: bark and foliage meshes of LOD0 and LOD1, then impostors.
    std::vector<gpu::DrawTemplate> templates;
    auto add = [&](const MeshRange& mesh, uint32_t drawClass, uint32_t model, uint32_t lod) {
        const uint32_t plantsOfModel = models[model].lists[PLANT_MODEL_LIST_CAPACITY];
        if (mesh.indexCount == 0 || plantsOfModel == 0) return;
        templates.push_back({glm::uvec4(mesh.indexCount, mesh.firstIndex, mesh.vertexOffset, drawClass),
                             glm::uvec4(model * LOD_COUNT + lod, pool.models[model].gpu.lists[lod], 0u, 0u)});
    };
    for (uint32_t drawClass : {uint32_t(DRAW_BARK), uint32_t(DRAW_FOLIAGE)})
        for (uint32_t m = 0; m < pool.models.size(); ++m)
            for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
                add(pool.models[m].meshes[lod][drawClass], drawClass, m, lod);
    for (uint32_t m = 0; m < pool.models.size(); ++m)
        add(billboards_[pool.models[m].gpu.impostor.z - 1], DRAW_IMPOSTOR, m, LOD_IMPOSTOR);

    const bool clustered = settings_.clusters.enabled;
    CullPassInputs inputs;
    inputs.instances = &instances_;
    inputs.models = &models_;
    inputs.instanceCount = plantCount;
    inputs.modelCount = uint32_t(pool.models.size());
    inputs.templates = templates;
    inputs.near = clustered ? &clusters_.near : nullptr;
    cull_ = createCullPass(resources_, inputs);
    inputs.kind = CullKind::ShadowCasters;
    inputs.near = clustered ? &shadowCacheClusters_.near : nullptr;
    shadowCacheCasters_ = createCullPass(resources_, inputs);
    inputs.near = clustered ? &shadowFrameClusters_.near : nullptr;
    shadowFrameCasters_ = createCullPass(resources_, inputs);
    createTracedSun(instances);
}

// The quadtree over the plants (in cluster order since buildFieldContent)
// and its three cuts: the camera's, and the leaves meeting the sun's boxes.
void FieldRenderer::createClusters(const std::vector<gpu::FieldInstance>& instances,
                                   const std::vector<gpu::PlantModel>& models) {
    clusterTree_ = buildClusterTree(instances, models, clusterRoot(content_.terrain), settings_.clusters.leafSide);
    clusterNodes_ = uploadVector(resources_, clusterTree_.nodes, kStorageAndTexels);
    CanopyBakeInputs bake;
    bake.tree = &clusterTree_;
    bake.nodes = &clusterNodes_;
    bake.instances = &instances_;
    bake.models = &models_;
    bake.atlas = &atlas_;
    bake.ground = &drawnTerrain_;
    bake.thresholdPixels = settings_.clusters.thresholdPixels;
    canopy_ = bakeCanopy(resources_, bake);
    const std::vector<uint32_t> mesh = canopyMeshIndices();
    canopyIndices_ = uploadVector(resources_, mesh, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    gpu::DrawCommand farMesh{};
    farMesh.indexCount = uint32_t(mesh.size());
    clusters_ = createClusterPass(resources_, clusterTree_, clusterNodes_, farMesh);
    shadowCacheClusters_ = createClusterPass(resources_, clusterTree_, clusterNodes_, farMesh);
    shadowFrameClusters_ = createClusterPass(resources_, clusterTree_, clusterNodes_, farMesh);
}

// The draw sets differ only in the visible list: the cull pass's lists,
// every plant once (naive), or the shadow casters' lists.
void FieldRenderer::createDescriptors() {
    const VkFormat uint4 = VK_FORMAT_R32G32B32A32_UINT;
    const VkFormat uint1 = VK_FORMAT_R32_UINT;
    auto texels = [&](uint32_t binding, const Buffer& buffer, VkFormat format) {
        return texelBuffer(binding, kDrawStages, createTexelView(resources_, buffer, format));
    };
    // Without clusters the canopy is never drawn; its bindings get one texel.
    const bool clustered = settings_.clusters.enabled;
    const Buffer placeholder = clustered ? Buffer{}
                                         : createBuffer(resources_, 16, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    const std::vector<DescriptorBinding> drawTable = {
        uniformBuffer(FIELD_BINDING_FRAME, kDrawStages, uniforms_),
        texels(FIELD_BINDING_INSTANCES, instances_, uint4),
        texels(FIELD_BINDING_VISIBLE, cull_.visible, uint1),
        texels(FIELD_BINDING_VERTICES, vertices_, uint4),
        texels(FIELD_BINDING_MODELS, models_, uint4),
        sampledImage(FIELD_BINDING_ATLAS_COLOR, kDrawStages, atlas_.sampler, atlas_.color.view),
        sampledImage(FIELD_BINDING_ATLAS_NORMAL, kDrawStages, atlas_.sampler, atlas_.normalDepth.view),
        sampledImage(FIELD_BINDING_IMPOSTOR_SHADOW, kDrawStages, atlas_.sampler, atlas_.shadow.view),
        sampledImage(FIELD_BINDING_SHADOW, kDrawStages, shadow_.sampler, shadow_.depth.view),
        texels(FIELD_BINDING_TERRAIN, terrainVertices_, uint4),
        texels(FIELD_BINDING_SKELETONS, motion_.pass.skeletons, uint4),
        texels(FIELD_BINDING_POSES, motion_.pass.poses, uint4),
        texels(FIELD_BINDING_INSTANCE_SKELETON, motion_.instanceSkeleton, uint1),
        texels(FIELD_BINDING_IMPOSTOR_OUTLINES, outlines_, uint4),
        texels(FIELD_BINDING_CLUSTER_NODES, clustered ? clusterNodes_ : placeholder, uint4),
        texels(FIELD_BINDING_CANOPY, clustered ? canopy_ : placeholder, uint4),
        texels(FIELD_BINDING_CANOPY_FAR, clustered ? clusters_.far : placeholder, uint1),
        tracedSunBinding(tracedSun_, kDrawStages)};
    auto withVisible = [&](const Buffer& visible) {
        std::vector<DescriptorBinding> table = drawTable;
        for (DescriptorBinding& b : table)
            if (b.binding == FIELD_BINDING_VISIBLE) b = texels(FIELD_BINDING_VISIBLE, visible, uint1);
        return table;
    };
    const std::vector<DescriptorBinding> naiveTable = withVisible(naiveVisible_);
    const std::vector<DescriptorBinding> shadowCacheTable = withVisible(shadowCacheCasters_.visible);
    const std::vector<DescriptorBinding> shadowFrameTable = withVisible(shadowFrameCasters_.visible);

    const VkDescriptorSetLayout setLayout = createSetLayout(resources_, drawTable);
    const DescriptorTable tables[] = {drawTable, naiveTable, shadowCacheTable, shadowFrameTable};
    const std::vector<VkDescriptorSet> sets = createSets(resources_, setLayout, tables);
    drawSet_ = sets[0];
    naiveSet_ = sets[1];
    shadowCacheSet_ = sets[2];
    shadowFrameSet_ = sets[3];
    pipelineLayout_ = createPipelineLayout(resources_, setLayout, {kDrawStages, 0, sizeof(gpu::FieldPush)});
}

void FieldRenderer::createPipelines() {
    GpuResources modules(ctx_);
    struct Stages {
        VkShaderModule vertex, fragment;
    };
    const Stages sky{createShaderModule(modules, spirv_sky_vert), createShaderModule(modules, spirv_sky_frag)};
    const Stages terrain{createShaderModule(modules, spirv_terrain_vert),
                         createShaderModule(modules, spirv_terrain_frag)};
    const Stages sunlitTerrain{terrain.vertex, createShaderModule(modules, spirv_terrain_sunlit_frag)};
    const Stages plant{createShaderModule(modules, spirv_plant_vert), createShaderModule(modules, spirv_plant_frag)};
    const Stages impostor{createShaderModule(modules, spirv_impostor_vert),
                          createShaderModule(modules, spirv_impostor_frag)};
    const Stages sunlitImpostor{impostor.vertex, createShaderModule(modules, spirv_impostor_sunlit_frag)};
    const Stages canopy{createShaderModule(modules, spirv_canopy_vert), createShaderModule(modules, spirv_canopy_frag)};
    const VkShaderModule plantShadow = createShaderModule(modules, spirv_plant_shadow_frag);
    const Stages impostorShadow{createShaderModule(modules, spirv_impostor_shadow_vert),
                                createShaderModule(modules, spirv_impostor_shadow_frag)};

    GraphicsPipelineDesc desc;
    desc.layout = pipelineLayout_;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = VkSampleCountFlagBits(colourPassSamples(settings_.antialiasing));
    auto make = [&](const Stages& s, VkCullModeFlags cull) {
        desc.vertex = s.vertex;
        desc.fragment = s.fragment;
        desc.cullMode = cull;
        return createGraphicsPipeline(resources_, desc);
    };
    // The sky lies on the far plane (depth 1, the clear value): drawn last,
    // it fills what nothing else covered, and writes no depth.
    desc.depthWrite = false;
    pipelines_.sky = make(sky, VK_CULL_MODE_NONE);
    desc.depthWrite = true;
    pipelines_.terrain = make(terrain, VK_CULL_MODE_BACK_BIT);
    pipelines_.sunlitTerrain = make(sunlitTerrain, VK_CULL_MODE_BACK_BIT);
    pipelines_.bark = make(plant, VK_CULL_MODE_BACK_BIT);
    pipelines_.foliage = make(plant, VK_CULL_MODE_NONE); // leaves are seen from both sides
    pipelines_.impostor = make(impostor, VK_CULL_MODE_NONE);
    pipelines_.sunlitImpostor = make(sunlitImpostor, VK_CULL_MODE_NONE);
    pipelines_.canopy = make(canopy, VK_CULL_MODE_NONE); // canopyMeshIndices: skirts last
    createTracedOriginPipelines(desc, {plant.vertex, impostor.vertex, terrain.vertex});

    // Depth only, seen from the sun: both sides of everything cast shadows.
    desc.colorFormat = VK_FORMAT_UNDEFINED;
    desc.depthFormat = kShadowFormat;
    desc.samples = VK_SAMPLE_COUNT_1_BIT;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE; // an ordinary viewport (shadow_map.h)
    desc.depthBiasConstant = 1.5f;
    desc.depthBiasSlope = 2.0f;
    pipelines_.plantShadow = make({plant.vertex, plantShadow}, VK_CULL_MODE_NONE);
    pipelines_.impostorShadow = make(impostorShadow, VK_CULL_MODE_NONE);
}

void FieldRenderer::setView(const FieldView& view, VkExtent2D extent) {
    const Environment env = environmentOf(content_.scene);
    FieldUniformBlock block{};
    block.frame = makeFrameUniforms(view.camera, env, {extent.width, extent.height}, view.time);
    planShadows(view, sunDirection(env), extent, block.frame.viewProj, block.field);
    block.field.viewport =
        glm::vec4(float(extent.width), float(extent.height), 2.0f * settings_.shadowRadius / float(shadow_.size),
                  settings_.shadows == SunShadows::none        ? FIELD_SUN_UNSHADOWED
                  : settings_.shadows == SunShadows::shadowMap ? FIELD_SUN_SHADOW_MAP
                                                               : FIELD_SUN_TRACED);
    sizeTracedSun(extent);
    advanceFieldMotion(motion_, view.time, view.firstFrame, view.camera.position, view.realTime);
    // The physics pass's wind field, for the shaders that sway without a skeleton.
    const gpu::PhysicsUniforms wind =
        makePhysicsUniforms(motion_.wind, motion_.settings, view.time, motion_.settings.subStep, 0, 0, 0);
    block.field.wind = glm::vec4(wind.wind.x, wind.wind.y, wind.wind.z, view.time);
    block.field.windDetail = glm::vec4(wind.windDetail.x, wind.windDetail.y, wind.wind.w, settings_.impostorSway);
    std::memcpy(uniforms_.mapped, &block, sizeof(block));
    setCloudView(clouds_, content_.scene, view.time, view.camera.position,
                 glm::normalize(view.camera.target - view.camera.position));
    cloudDrift_ = meanWindVelocity(content_.scene.wind) * view.time;
    // The shaders look the shadow up 1.5 texels along the normal (sunMapPosition).
    const float shadowTexel = 2.0f * settings_.shadowRadius / float(shadow_.size);
    terrainRanges_ = visibleTerrainRanges(terrainChunks_, block.frame.viewProj, view.camera.position,
                                          pixelsPerMetre(glm::radians(view.camera.fovYDegrees), extent.height),
                                          settings_.shadows != SunShadows::none ? std::optional(block.field.sunViewProj)
                                                                                : std::nullopt,
                                          2.0f * shadowTexel);

    gpu::CullUniforms cull =
        makeCullUniforms(block.frame.viewProj, view.camera.position, glm::radians(view.camera.fovYDegrees),
                         extent.height, view.deltaTime, view.firstFrame, view.forcedLod.value_or(0xFFFFFFFFu));
    const glm::uvec2 viewport(extent.width, extent.height);
    setOcclusionUniforms(cull, viewMatrix(view.camera), projectionMatrix(view.camera, viewport), viewport,
                         view.camera.nearPlane, uint32_t(depthPyramidExtents({extent.width, extent.height}).size()));
    setCullUniforms(cull_, cull);
    if (!settings_.clusters.enabled) return;
    const uint32_t cut = view.forcedCut.value_or(CLUSTER_CUT_AUTO);
    setClusterUniforms(clusters_, makeClusterUniforms(frustumPlanes(block.frame.viewProj), cull.camera, cut,
                                                      settings_.clusters.thresholdPixels, view.firstFrame));
    // The canopy draw is recorded only when some leaf can be far (its cell
    // below the threshold at the field's farthest point): most views of a
    // small field have no far node.
    const gpu::ClusterNode& root = clusterTree_.nodes.back();
    const glm::vec3 camera = view.camera.position;
    const glm::vec3 farthest =
        glm::max(glm::abs(camera - glm::vec3(root.boxMin)), glm::abs(camera - glm::vec3(root.boxMax)));
    const float leafPixels =
        gpu::pixelsAtDistance(0.5f * clusterTree_.nodes[0].square.w, cull.camera.w, glm::length(farthest));
    drawCanopy_ =
        cut == CLUSTER_CUT_ALL_FAR || (cut == CLUSTER_CUT_AUTO && leafPixels < settings_.clusters.thresholdPixels);
}

void FieldRenderer::pushFieldPass(VkCommandBuffer cmd, uint32_t pass, uint32_t impostorPart) const {
    const gpu::FieldPush push{pass, impostorPart};
    vkCmdPushConstants(cmd, pipelineLayout_, kDrawStages, 0, sizeof(push), &push);
}

// The plants a cull phase listed: bark, foliage, then impostors.
void FieldRenderer::drawPlantLists(VkCommandBuffer cmd, uint32_t phase, GpuTimer* timer) const {
    const bool late = phase == CULL_PHASE_LATE;
    {
        TimedFieldScope scope(cmd, late ? nullptr : timer, FieldScope::plants, ScopeStart::insideRendering);
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.bark);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_BARK, phase);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.foliage);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_FOLIAGE, phase);
    }
    {
        // The list twice: those the shadow map may reach, then the rest with
        // no shadow lookup (shaders/sunlit_select.h); each draw drops the
        // other's impostors in its vertex shader.
        TimedFieldScope scope(cmd, late ? nullptr : timer, FieldScope::impostors, ScopeStart::insideRendering);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.impostor);
        pushFieldPass(cmd, FIELD_PASS_COLOUR, IMPOSTOR_PART_SHADOWED);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_IMPOSTOR, phase);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sunlitImpostor);
        pushFieldPass(cmd, FIELD_PASS_COLOUR, IMPOSTOR_PART_SUNLIT);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_IMPOSTOR, phase);
    }
}

// Between the colour pass's two parts: the depth pyramid of what the early
// phase drew (the terrain the main occluder), the late cull against it, and
// the plants it found visible drawn into the loaded colour and depth.
void FieldRenderer::recordLatePhase(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    vkCmdEndRendering(cmd);
    {
        TimedFieldScope scope(cmd, timer, FieldScope::depthPyramid);
        recordDepthPyramid(cmd, target.pyramid);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::occlusion);
        recordCullPass(cmd, cull_, CULL_PHASE_LATE, target.pyramid.readSet);
    }
    TimedFieldScope scope(cmd, timer, FieldScope::lateDraws);
    beginTargetPass(cmd, target, TargetPassPart::last);
    pushFieldPass(cmd, FIELD_PASS_COLOUR);
    drawPlantLists(cmd, CULL_PHASE_LATE, timer);
}

void FieldRenderer::recordColourPass(VkCommandBuffer cmd, const RenderTarget& target, bool naive,
                                     GpuTimer* timer) const {
    // The whole pass, anti-aliasing included, is one scope: tiling and CPU
    // rasterisers (lavapipe) shade at the end of the pass, so the draw scopes
    // inside it measure only their share of vertex work and binning there.
    // The FXAA pass (FieldScope::antialias) is a rendering of its own after it.
    TimedFieldScope pass(cmd, timer, FieldScope::colour);
    const bool twoParts = !naive && occlusion();
    const VkDescriptorSet set = naive ? naiveSet_ : drawSet_;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
    beginTargetPass(cmd, target, twoParts ? TargetPassPart::first : TargetPassPart::whole);
    pushFieldPass(cmd, FIELD_PASS_COLOUR);
    if (naive) {
        {
            TimedFieldScope scope(cmd, timer, FieldScope::plants, ScopeStart::insideRendering);
            vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.bark);
            drawPlantsNaive(cmd, true, false);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.foliage);
            drawPlantsNaive(cmd, false, true);
        }
        TimedFieldScope scope(cmd, timer, FieldScope::impostors,
                              ScopeStart::insideRendering); // the naive baseline draws no impostors
    } else {
        drawPlantLists(cmd, twoParts ? CULL_PHASE_EARLY : CULL_PHASE_ALL, timer);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::canopy, ScopeStart::insideRendering);
        if (!naive && settings_.clusters.enabled && drawCanopy_) {
            // One instance per far node; the cluster pass wrote the count.
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.canopy);
            vkCmdBindIndexBuffer(cmd, canopyIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
            drawCanopyIndirect(cmd, ctx_, clusters_);
        }
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::terrainSky, ScopeStart::insideRendering);
        // Last, behind everything: only pixels no plant covers are shaded
        // (the depth test runs before these shaders, which never discard).
        // With occlusion culling the terrain is the early phase's main
        // occluder; the sky, drawn with it, writes no depth and is covered
        // by what the late phase draws.
        vkCmdBindIndexBuffer(cmd, terrainIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.terrain);
        for (const IndexRange& range : terrainRanges_.shadowed)
            vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sunlitTerrain);
        for (const IndexRange& range : terrainRanges_.sunlit)
            vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sky);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    if (twoParts) {
        recordLatePhase(cmd, target, timer);
    } else {
        // Every frame has the same scopes.
        for (FieldScope late : {FieldScope::depthPyramid, FieldScope::occlusion, FieldScope::lateDraws})
            TimedFieldScope scope(cmd, timer, late, ScopeStart::insideRendering);
    }
    {
        // Last, over everything opaque and the sky: their shadows on the
        // ground, then the clouds back to front.
        TimedFieldScope scope(cmd, timer, FieldScope::clouds, ScopeStart::insideRendering);
        recordCloudShadowPass(cmd, cloudShadows_, terrainIndices_, terrainRanges_, cloudDrift_);
        recordCloudPass(cmd, clouds_);
    }
    endTargetPass(cmd, target, timer);
}

void FieldRenderer::record(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    recordFieldMotion(cmd, motion_, timer);
    {
        TimedFieldScope scope(cmd, timer, FieldScope::clusters);
        if (settings_.clusters.enabled) recordClusterPass(cmd, clusters_);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::cull);
        recordCullPass(cmd, cull_, occlusion() ? CULL_PHASE_EARLY : CULL_PHASE_ALL);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::shadow);
        if (settings_.shadows == SunShadows::shadowMap) recordShadowPass(cmd);
        if (settings_.shadows == SunShadows::traced) recordTracedSunPass(cmd, false);
    }
    recordColourPass(cmd, target, false, timer);
}

void FieldRenderer::recordNaive(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    recordFieldMotion(cmd, motion_, timer);
    { TimedFieldScope scope(cmd, timer, FieldScope::clusters); }
    { TimedFieldScope scope(cmd, timer, FieldScope::cull); }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::shadow);
        if (settings_.shadows == SunShadows::shadowMap) recordNaiveShadowPass(cmd);
        if (settings_.shadows == SunShadows::traced) recordTracedSunPass(cmd, true);
    }
    recordColourPass(cmd, target, true, timer);
}

// One draw per plant and class, its full-detail mesh; firstInstance picks the
// plant's entry of the identity list.
void FieldRenderer::drawPlantsNaive(VkCommandBuffer cmd, bool bark, bool foliage) const {
    const PlantModelPool& pool = content_.models;
    for (uint32_t i = 0; i < content_.plants.size(); ++i) {
        const PlantInstance& p = content_.plants[i];
        const PlantModelInfo& model = pool.models[pool.modelOf(p.species, p.variant)];
        for (uint32_t drawClass = 0; drawClass < kMeshClassCount; ++drawClass) {
            if ((drawClass == DRAW_BARK && !bark) || (drawClass == DRAW_FOLIAGE && !foliage)) continue;
            const MeshRange& mesh = model.meshes[LOD_FULL][drawClass];
            if (mesh.indexCount > 0)
                vkCmdDrawIndexed(cmd, mesh.indexCount, 1, mesh.firstIndex, int32_t(mesh.vertexOffset), i);
        }
    }
}

VkDeviceSize FieldRenderer::gpuBytes() const { return resources_.bytes() + tracedSun_.images.resources->bytes(); }

} // namespace pf
