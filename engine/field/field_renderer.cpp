#include "engine/field/field_renderer.h"

#include "engine/vk/gpu_timer.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "engine/vk/vk_check.h"

#include "shaders/impostor_frag.spv.h"
#include "shaders/impostor_shadow_frag.spv.h"
#include "shaders/impostor_vert.spv.h"
#include "shaders/plant_frag.spv.h"
#include "shaders/plant_shadow_frag.spv.h"
#include "shaders/plant_vert.spv.h"
#include "shaders/sky_frag.spv.h"
#include "shaders/sky_vert.spv.h"
#include "shaders/terrain_frag.spv.h"
#include "shaders/terrain_vert.spv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
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

struct Timed {
    VkCommandBuffer cmd;
    GpuTimer* timer;
    Timed(VkCommandBuffer c, GpuTimer* t, const char* name) : cmd(c), timer(t) {
        if (timer) beginScope(cmd, *timer, name);
    }
    ~Timed() {
        if (timer) endScope(cmd, *timer);
    }
};

template <class T>
Buffer uploadVector(const GpuContext& ctx, const std::vector<T>& data, VkBufferUsageFlags usage) {
    if (data.empty()) throw std::runtime_error("field renderer: nothing to upload");
    return createDeviceBufferWithData(ctx, data.data(), data.size() * sizeof(T), usage);
}

// The drawn terrain keeps at most this many samples a side: far cells of a
// finer grid are a pixel or two wide, and a CPU rasteriser pays per triangle.
constexpr uint32_t kTerrainDrawSamples = 129;

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

bool nestedInColourPass(std::string_view pass) {
    const auto colour = std::find(std::begin(kFieldPasses), std::end(kFieldPasses), std::string_view("colour"));
    return std::find(std::next(colour), std::end(kFieldPasses), pass) != std::end(kFieldPasses);
}

FieldRenderer::FieldRenderer(const GpuContext& ctx, FieldContent content, const FieldRenderSettings& settings)
    : ctx_(ctx), content_(std::move(content)), settings_(settings) {
    if (content_.plants.empty()) throw std::runtime_error("the scene places no plant");
    if (content_.plants.size() > FIELD_MAX_INSTANCES)
        throw std::runtime_error("at most " + std::to_string(FIELD_MAX_INSTANCES) + " plants can be drawn");
    uniforms_ = createHostBuffer(ctx_, sizeof(FieldUniformBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    uploadGeometry();
    uploadInstances();
    motion_ = createFieldMotion(ctx_, content_);
    shadow_ = createShadowMap(ctx_, settings_.shadowMapSize);
    createDescriptors();
    createPipelines();
}

FieldRenderer::~FieldRenderer() {
    VkDevice device = ctx_.device;
    vkDeviceWaitIdle(device);
    for (VkPipeline p : {pipelines_.sky, pipelines_.terrain, pipelines_.bark, pipelines_.foliage, pipelines_.impostor,
                         pipelines_.plantShadow, pipelines_.impostorShadow})
        vkDestroyPipeline(device, p, nullptr);
    vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
    vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
    for (VkBufferView view : texelViews_) vkDestroyBufferView(device, view, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    destroyCullPass(ctx_, cull_);
    destroyFieldMotion(ctx_, motion_);
    destroyShadowMap(ctx_, shadow_);
    destroyImpostorAtlas(ctx_, atlas_);
    for (Buffer* b : {&uniforms_, &vertices_, &indices_, &models_, &instances_, &terrainVertices_, &terrainIndices_,
                      &naiveVisible_, &outlines_})
        destroyBuffer(ctx_, *b);
}

// Plant meshes and billboards in one vertex and one index pool, the
// impostors baked from them, and the terrain.
void FieldRenderer::uploadGeometry() {
    PlantModelPool& pool = content_.models;
    for (uint32_t quads = 1; quads <= 3; ++quads) billboards_[quads - 1] = appendBillboardMesh(pool, quads);
    vertices_ = uploadVector(ctx_, pool.vertices, kStorageAndTexels);
    indices_ = uploadVector(ctx_, pool.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    atlas_ = bakeImpostorAtlas(ctx_, pool, vertices_, indices_, settings_.impostors);
    outlines_ = uploadVector(ctx_, atlas_.outlines, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);

    const TerrainMesh mesh = makeTerrainMesh(decimated(content_.terrain, kTerrainDrawSamples));
    std::vector<gpu::TerrainVertex> terrain(mesh.positions.size());
    for (size_t i = 0; i < terrain.size(); ++i)
        terrain[i] = {glm::vec4(mesh.positions[i], 0.0f), glm::vec4(mesh.normals[i], 0.0f)};
    terrainVertices_ = uploadVector(ctx_, terrain, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    terrainIndices_ = uploadVector(ctx_, mesh.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    terrainIndexCount_ = uint32_t(mesh.indices.size());
}

// Instances, the models with their visible-list regions (assignVisibleLists),
// and the draw templates of the cull pass.
void FieldRenderer::uploadInstances() {
    PlantModelPool& pool = content_.models;
    const uint32_t plantCount = uint32_t(content_.plants.size());
    std::vector<gpu::FieldInstance> instances(plantCount);
    for (uint32_t i = 0; i < plantCount; ++i) {
        const PlantInstance& p = content_.plants[i];
        instances[i] = {glm::vec4(p.position, p.scale), glm::vec4(p.rotation, p.windPhase, 0.0f, 0.0f),
                        glm::uvec4(pool.modelOf(p.species, p.variant), p.species, p.variant, 0u)};
    }
    std::vector<gpu::PlantModel> models;
    for (const PlantModelInfo& info : pool.models) models.push_back(info.gpu);
    assignVisibleLists(models, instances);
    for (size_t m = 0; m < pool.models.size(); ++m) pool.models[m].gpu.lists = models[m].lists;
    models_ = uploadVector(ctx_, models, kStorageAndTexels);
    instances_ = uploadVector(ctx_, instances, kStorageAndTexels);

    std::vector<uint32_t> naive(plantCount);
    for (uint32_t i = 0; i < plantCount; ++i) naive[i] = i | (VISIBLE_COVERAGE_MAX << VISIBLE_COVERAGE_SHIFT);
    naiveVisible_ = uploadVector(ctx_, naive, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);

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

    CullPassInputs inputs;
    inputs.instances = &instances_;
    inputs.models = &models_;
    inputs.instanceCount = plantCount;
    inputs.modelCount = uint32_t(pool.models.size());
    inputs.templates = templates;
    cull_ = createCullPass(ctx_, inputs);
}

void FieldRenderer::createDescriptors() {
    const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    const VkDescriptorType image = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorSetLayoutBinding bindings[] = {
        {FIELD_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kDrawStages, nullptr},
        {FIELD_BINDING_INSTANCES, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_VISIBLE, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_VERTICES, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_MODELS, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_ATLAS_COLOR, image, 1, kDrawStages, nullptr},
        {FIELD_BINDING_ATLAS_NORMAL, image, 1, kDrawStages, nullptr},
        {FIELD_BINDING_SHADOW, image, 1, kDrawStages, nullptr},
        {FIELD_BINDING_TERRAIN, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_SKELETONS, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_POSES, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_INSTANCE_SKELETON, texels, 1, kDrawStages, nullptr},
        {FIELD_BINDING_IMPOSTOR_OUTLINES, texels, 1, kDrawStages, nullptr},
    };
    constexpr uint32_t kBindings = uint32_t(std::size(bindings));
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = kBindings;
    layoutInfo.pBindings = bindings;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &layoutInfo, nullptr, &setLayout_));

    // Two sets (GPU-driven and naive) of the layout above.
    descriptorPool_ = createDescriptorPool(ctx_, bindings, 2);

    const VkDescriptorSetLayout layouts[] = {setLayout_, setLayout_};
    VkDescriptorSet sets[2];
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = descriptorPool_;
    alloc.descriptorSetCount = 2;
    alloc.pSetLayouts = layouts;
    VK_CHECK(vkAllocateDescriptorSets(ctx_.device, &alloc, sets));
    drawSet_ = sets[0];
    naiveSet_ = sets[1];

    const VkFormat uint4 = VK_FORMAT_R32G32B32A32_UINT;
    auto view = [&](const Buffer& buffer, VkFormat format, uint32_t bytes) {
        texelViews_.push_back(createTexelView(ctx_, buffer, format, bytes));
        return texelViews_.back();
    };
    const VkBufferView instances = view(instances_, uint4, 16), vertices = view(vertices_, uint4, 16),
                       models = view(models_, uint4, 16), terrain = view(terrainVertices_, uint4, 16),
                       skeletons = view(motion_.pass.skeletons, uint4, 16), poses = view(motion_.pass.poses, uint4, 16),
                       instanceSkeleton = view(motion_.instanceSkeleton, VK_FORMAT_R32_UINT, 4),
                       outlines = view(outlines_, uint4, 16);
    const VkDescriptorBufferInfo frame{uniforms_.buffer, 0, VK_WHOLE_SIZE};
    const VkDescriptorImageInfo atlasColor{atlas_.sampler, atlas_.color.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo atlasNormal{atlas_.sampler, atlas_.normalDepth.view,
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo shadow{shadow_.sampler, shadow_.depth.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    for (VkDescriptorSet set : sets) {
        const VkBufferView visible = view(set == drawSet_ ? cull_.visible : naiveVisible_, VK_FORMAT_R32_UINT, 4);
        // Indexed by binding, like `images`; the frame is the one plain buffer.
        const VkBufferView views[] = {VK_NULL_HANDLE, instances,        visible,        vertices, models,
                                      VK_NULL_HANDLE, VK_NULL_HANDLE,   VK_NULL_HANDLE, terrain,  skeletons,
                                      poses,          instanceSkeleton, outlines};
        const VkDescriptorImageInfo* images[] = {nullptr, nullptr, nullptr, nullptr, nullptr, &atlasColor, &atlasNormal,
                                                 &shadow, nullptr, nullptr, nullptr, nullptr, nullptr};
        VkWriteDescriptorSet writes[kBindings];
        for (uint32_t i = 0; i < kBindings; ++i) {
            writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[i].dstSet = set;
            writes[i].dstBinding = bindings[i].binding;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = bindings[i].descriptorType;
            if (images[i])
                writes[i].pImageInfo = images[i];
            else if (views[i])
                writes[i].pTexelBufferView = &views[i];
            else
                writes[i].pBufferInfo = &frame;
        }
        vkUpdateDescriptorSets(ctx_.device, kBindings, writes, 0, nullptr);
    }

    const VkPushConstantRange push{kDrawStages, 0, sizeof(uint32_t)};
    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &setLayout_;
    pipelineLayoutInfo.pushConstantRangeCount = 1;
    pipelineLayoutInfo.pPushConstantRanges = &push;
    VK_CHECK(vkCreatePipelineLayout(ctx_.device, &pipelineLayoutInfo, nullptr, &pipelineLayout_));
}

void FieldRenderer::createPipelines() {
    VkDevice device = ctx_.device;
    struct Stages {
        VkShaderModule vertex, fragment;
    };
    const Stages sky{createShaderModule(device, spirv_sky_vert), createShaderModule(device, spirv_sky_frag)};
    const Stages terrain{createShaderModule(device, spirv_terrain_vert),
                         createShaderModule(device, spirv_terrain_frag)};
    const Stages plant{createShaderModule(device, spirv_plant_vert), createShaderModule(device, spirv_plant_frag)};
    const Stages impostor{createShaderModule(device, spirv_impostor_vert),
                          createShaderModule(device, spirv_impostor_frag)};
    const VkShaderModule plantShadow = createShaderModule(device, spirv_plant_shadow_frag);
    const VkShaderModule impostorShadow = createShaderModule(device, spirv_impostor_shadow_frag);

    GraphicsPipelineDesc desc;
    desc.layout = pipelineLayout_;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = settings_.samples;
    auto make = [&](const Stages& s, VkCullModeFlags cull) {
        desc.vertex = s.vertex;
        desc.fragment = s.fragment;
        desc.cullMode = cull;
        return createGraphicsPipeline(device, desc);
    };
    // The sky lies on the far plane (depth 1, the clear value): drawn last,
    // it fills what nothing else covered, and writes no depth.
    desc.depthWrite = false;
    pipelines_.sky = make(sky, VK_CULL_MODE_NONE);
    desc.depthWrite = true;
    pipelines_.terrain = make(terrain, VK_CULL_MODE_BACK_BIT);
    pipelines_.bark = make(plant, VK_CULL_MODE_BACK_BIT);
    pipelines_.foliage = make(plant, VK_CULL_MODE_NONE); // leaves are seen from both sides
    pipelines_.impostor = make(impostor, VK_CULL_MODE_NONE);

    // Depth only, seen from the sun: both sides of everything cast shadows.
    desc.colorFormat = VK_FORMAT_UNDEFINED;
    desc.depthFormat = kShadowFormat;
    desc.samples = VK_SAMPLE_COUNT_1_BIT;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE; // an ordinary viewport (shadow_map.h)
    desc.depthBiasConstant = 1.5f;
    desc.depthBiasSlope = 2.0f;
    pipelines_.plantShadow = make({plant.vertex, plantShadow}, VK_CULL_MODE_NONE);
    pipelines_.impostorShadow = make({impostor.vertex, impostorShadow}, VK_CULL_MODE_NONE);

    for (const Stages& s : {sky, terrain, plant, impostor}) {
        vkDestroyShaderModule(device, s.vertex, nullptr);
        vkDestroyShaderModule(device, s.fragment, nullptr);
    }
    vkDestroyShaderModule(device, plantShadow, nullptr);
    vkDestroyShaderModule(device, impostorShadow, nullptr);
}

void FieldRenderer::setView(const FieldView& view, VkExtent2D extent) {
    const Environment env = environmentOf(content_.scene);
    FieldUniformBlock block{};
    block.frame = makeFrameUniforms(view.camera, env, {extent.width, extent.height}, view.time);

    const glm::vec3 forward = glm::normalize(view.camera.target - view.camera.position);
    // Shadows where they are seen large: a square reaching ahead of the camera.
    const float radius = settings_.shadowRadius;
    const glm::vec3 flatForward = glm::length(glm::vec2(forward.x, forward.z)) > 1e-3f
                                      ? glm::normalize(glm::vec3(forward.x, 0.0f, forward.z))
                                      : glm::vec3(0.0f);
    const glm::vec3 focus = view.camera.position + flatForward * (0.6f * radius);
    block.field.sunViewProj = sunViewProjection(sunDirection(env), focus, radius, 250.0f, shadow_.size);
    block.field.viewport = glm::vec4(float(extent.width), float(extent.height), 2.0f * radius / float(shadow_.size),
                                     settings_.shadows ? 1.0f : 0.0f);
    advanceFieldMotion(motion_, view.time, view.firstFrame, view.camera.position, view.realTime);
    // The physics pass's wind field, for the shaders that sway without a skeleton.
    const gpu::PhysicsUniforms wind =
        makePhysicsUniforms(motion_.wind, motion_.settings, view.time, motion_.settings.subStep, 0, 0, 0);
    block.field.wind = glm::vec4(wind.wind.x, wind.wind.y, wind.wind.z, view.time);
    block.field.windDetail = glm::vec4(wind.windDetail.x, wind.windDetail.y, wind.wind.w, settings_.impostorSway);
    std::memcpy(uniforms_.mapped, &block, sizeof(block));

    setCullUniforms(cull_, makeCullUniforms(block.frame.viewProj, view.camera.position,
                                            glm::radians(view.camera.fovYDegrees), extent.height, view.deltaTime,
                                            view.firstFrame, view.forcedLod.value_or(0xFFFFFFFFu)));
}

void FieldRenderer::recordShadowPass(VkCommandBuffer cmd, bool naive) const {
    beginShadowPass(cmd, shadow_);
    const uint32_t shadowPass = 1;
    vkCmdPushConstants(cmd, pipelineLayout_, kDrawStages, 0, sizeof(shadowPass), &shadowPass);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.plantShadow);
    vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    if (naive) {
        drawPlantsNaive(cmd, true, true);
    } else {
        drawClassIndirect(cmd, ctx_, cull_, DRAW_BARK);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_FOLIAGE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.impostorShadow);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_IMPOSTOR);
    }
    endShadowPass(cmd, shadow_);
}

void FieldRenderer::recordColourPass(VkCommandBuffer cmd, const RenderTarget& target, bool naive,
                                     GpuTimer* timer) const {
    // The whole pass, resolve included, is one scope: tiling and CPU
    // rasterisers (lavapipe) shade at the end of the pass, so the scopes
    // inside it measure only their share of vertex work and binning there.
    Timed pass(cmd, timer, "colour");
    beginTargetPass(cmd, target);
    const uint32_t colourPass = 0;
    vkCmdPushConstants(cmd, pipelineLayout_, kDrawStages, 0, sizeof(colourPass), &colourPass);
    {
        Timed scope(cmd, timer, "plants");
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.bark);
        if (naive)
            drawPlantsNaive(cmd, true, false);
        else
            drawClassIndirect(cmd, ctx_, cull_, DRAW_BARK);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.foliage);
        if (naive)
            drawPlantsNaive(cmd, false, true);
        else
            drawClassIndirect(cmd, ctx_, cull_, DRAW_FOLIAGE);
    }
    {
        Timed scope(cmd, timer, "impostors");
        if (!naive) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.impostor);
            drawClassIndirect(cmd, ctx_, cull_, DRAW_IMPOSTOR);
        }
    }
    {
        Timed scope(cmd, timer, "terrain_sky");
        // Last, behind everything: only pixels no plant covers are shaded
        // (the depth test runs before these shaders, which never discard).
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.terrain);
        vkCmdBindIndexBuffer(cmd, terrainIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, terrainIndexCount_, 1, 0, 0, 0);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sky);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    endTargetPass(cmd, target);
}

void FieldRenderer::record(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &drawSet_, 0, nullptr);
    recordFieldMotion(cmd, motion_, timer);
    {
        Timed scope(cmd, timer, "cull");
        recordCullPass(cmd, cull_);
    }
    {
        Timed scope(cmd, timer, "shadow");
        if (settings_.shadows) recordShadowPass(cmd, false);
    }
    recordColourPass(cmd, target, false, timer);
}

void FieldRenderer::recordNaive(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const {
    if (timer) resetGpuTimer(cmd, *timer);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &naiveSet_, 0, nullptr);
    recordFieldMotion(cmd, motion_, timer);
    { Timed scope(cmd, timer, "cull"); }
    {
        Timed scope(cmd, timer, "shadow");
        if (settings_.shadows) recordShadowPass(cmd, true);
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

uint32_t FieldFrameStats::visibleEntries() const {
    uint32_t entries = 0;
    for (uint32_t plants : plantsPerLod) entries += plants;
    return entries;
}

uint32_t FieldFrameStats::culled() const { return instances > visibleEntries() ? instances - visibleEntries() : 0; }

std::string plantsPerLodText(const FieldFrameStats& stats) {
    std::string text;
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
        text += (lod ? "  " : "") + std::string(kLodNames[lod]) + " " + std::to_string(stats.plantsPerLod[lod]);
    return text;
}

FieldFrameStats FieldRenderer::readStats() const {
    const CullCounts counts = readCullCounts(cull_);
    FieldFrameStats stats;
    stats.instances = uint32_t(content_.plants.size());
    stats.plantsPerLod = counts.perLod;
    stats.draws = counts.drawsPerClass;
    const PlantModelPool& pool = content_.models;
    for (size_t m = 0; m < pool.models.size(); ++m) {
        const PlantModelInfo& model = pool.models[m];
        for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
            stats.triangles += uint64_t(counts.perModelLod[m * LOD_COUNT + lod]) * model.triangles(lod);
        stats.triangles +=
            uint64_t(counts.perModelLod[m * LOD_COUNT + LOD_IMPOSTOR]) * (kOutlineCorners - 2) * model.gpu.impostor.z;
    }
    return stats;
}

uint64_t FieldRenderer::naiveTriangles() const {
    uint64_t triangles = 0;
    const PlantModelPool& pool = content_.models;
    for (const PlantInstance& p : content_.plants)
        triangles += pool.models[pool.modelOf(p.species, p.variant)].triangles(LOD_FULL);
    return triangles;
}

VkDeviceSize FieldRenderer::gpuBytes() const {
    VkDeviceSize bytes = 0;
    for (const Buffer* b : {&uniforms_,
                            &vertices_,
                            &indices_,
                            &models_,
                            &instances_,
                            &terrainVertices_,
                            &terrainIndices_,
                            &naiveVisible_,
                            &outlines_,
                            &cull_.uniforms,
                            &cull_.templates,
                            &cull_.state,
                            &cull_.counts,
                            &cull_.visible,
                            &cull_.commands,
                            &cull_.drawCounts,
                            &cull_.allCommands,
                            &cull_.readback,
                            &motion_.pass.uniforms,
                            &motion_.pass.params,
                            &motion_.pass.skeletons,
                            &motion_.pass.states,
                            &motion_.pass.poses,
                            &motion_.pass.jointSkeleton,
                            &motion_.instanceSkeleton,
                            &motion_.restStates,
                            &motion_.restPoses})
        bytes += b->size;
    auto imageBytes = [](const Image& image, uint32_t layers, uint32_t bytesPerTexel, double mipFactor) {
        return VkDeviceSize(double(image.extent.width) * image.extent.height * layers * bytesPerTexel * mipFactor);
    };
    bytes += imageBytes(atlas_.color, atlas_.layers, 4, 4.0 / 3.0) +
             imageBytes(atlas_.normalDepth, atlas_.layers, 4, 4.0 / 3.0);
    bytes += imageBytes(shadow_.depth, 1, 4, 1.0);
    return bytes;
}

} // namespace pf
