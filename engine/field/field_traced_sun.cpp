// The FieldRenderer's ray-traced sun shadows (traced_sun_pass.h): the pass
// made with the field's graph, its images sized to the frame, the origins
// pass drawing what the colour pass will show, and the trace.
#include "engine/field/field_renderer.h"

#include "engine/raytrace/field_graph.h"
#include "engine/vk/descriptors.h"

#include "shaders/traced_origin_impostor_frag.spv.h"
#include "shaders/traced_origin_plant_frag.spv.h"
#include "shaders/traced_origin_terrain_frag.spv.h"

#include <cmath>
#include <utility>

namespace pf {

void FieldRenderer::createTracedSun(const std::vector<gpu::FieldInstance>& instances) {
    if (settings_.shadows != SunShadows::traced) {
        tracedSun_ = createUntracedSunPass(resources_);
        return;
    }
    // A ray from anywhere on the field reaches past every plant within the
    // diagonal of the terrain and the height of the tallest crown.
    float top = 0.0f;
    for (const PlantModelInfo& model : content_.models.models) top = std::max(top, model.gpu.boxMax.y);
    float highest = 0.0f;
    for (const PlantInstance& plant : content_.plants) highest = std::max(highest, plant.scale);
    const float reach = std::sqrt(2.0f) * content_.terrain.size + top * highest + 1000.0f;
    lsys::need(settings_.memory, "the field's graph for ray-traced shadows",
               fieldGraphBytes(content_.models, content_.plants.size()));
    tracedSun_ = createTracedSunPass(resources_, content_.models, instances, reach);
}

void FieldRenderer::createTracedOriginPipelines(GraphicsPipelineDesc desc, const TracedOriginVertices& vertices) {
    if (settings_.shadows != SunShadows::traced) return;
    GpuResources modules(ctx_);
    const VkShaderModule plantOrigin = createShaderModule(modules, spirv_traced_origin_plant_frag);
    const VkShaderModule terrainOrigin = createShaderModule(modules, spirv_traced_origin_terrain_frag);
    const VkShaderModule impostorOrigin = createShaderModule(modules, spirv_traced_origin_impostor_frag);
    desc.colorFormat = kTracedOriginFormat;
    desc.depthFormat = VK_FORMAT_D32_SFLOAT;
    desc.samples = VK_SAMPLE_COUNT_1_BIT;
    desc.depthWrite = true;
    auto make = [&](VkShaderModule vertex, VkShaderModule fragment, VkCullModeFlags cull) {
        desc.vertex = vertex;
        desc.fragment = fragment;
        desc.cullMode = cull;
        return createGraphicsPipeline(resources_, desc);
    };
    // Culled as the colour pass culls them, so each pixel's origin is of the surface it will show.
    pipelines_.originBark = make(vertices.plant, plantOrigin, VK_CULL_MODE_BACK_BIT);
    pipelines_.originFoliage = make(vertices.plant, plantOrigin, VK_CULL_MODE_NONE);
    pipelines_.originImpostor = make(vertices.impostor, impostorOrigin, VK_CULL_MODE_NONE);
    pipelines_.originTerrain = make(vertices.terrain, terrainOrigin, VK_CULL_MODE_BACK_BIT);
}

// The colour pass's sets sample the visibility of the frame's size.
void FieldRenderer::sizeTracedSun(VkExtent2D extent) {
    if (settings_.shadows != SunShadows::traced || !resizeTracedSunImages(ctx_, tracedSun_, extent)) return;
    // A write names no stages: the sets' layout keeps the colour pass's.
    const DescriptorBinding visibility = tracedSunBinding(tracedSun_, VK_SHADER_STAGE_FRAGMENT_BIT);
    for (VkDescriptorSet set : {drawSet_, naiveSet_, shadowCacheSet_, shadowFrameSet_})
        writeSet(ctx_.device, set, {&visibility, 1});
}

// The origins of the plant meshes the colour pass will draw (the cull
// pass's lists, or every plant at full detail for the naive baseline), of
// the impostors and terrain chunks the sun's square reaches, then the trace.
void FieldRenderer::recordTracedSunPass(VkCommandBuffer cmd, bool naive) const {
    beginTracedOrigins(cmd, tracedSun_.images);
    const VkDescriptorSet set = naive ? naiveSet_ : drawSet_;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
    pushFieldPass(cmd, FIELD_PASS_COLOUR);
    vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    for (const auto& [drawClass, pipeline] : {std::pair{uint32_t(DRAW_BARK), pipelines_.originBark},
                                              std::pair{uint32_t(DRAW_FOLIAGE), pipelines_.originFoliage}}) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        if (naive)
            drawPlantsNaive(cmd, drawClass == DRAW_BARK, drawClass == DRAW_FOLIAGE);
        else
            drawClassIndirect(cmd, ctx_, cull_, drawClass, CULL_PHASE_ALL);
    }
    if (!naive) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.originImpostor);
        pushFieldPass(cmd, FIELD_PASS_COLOUR, IMPOSTOR_PART_SHADOWED);
        drawClassIndirect(cmd, ctx_, cull_, DRAW_IMPOSTOR, CULL_PHASE_ALL);
    }
    vkCmdBindIndexBuffer(cmd, terrainIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.originTerrain);
    for (const IndexRange& range : terrainRanges_.shadowed)
        vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
    endTracedOrigins(cmd, tracedSun_.images);
    recordTracedSun(cmd, tracedSun_, sunDirection(environmentOf(content_.scene)));
}

} // namespace pf
