#include "engine/field/raytraced_origins_pass.h"

#include "engine/field/draw_sets.h"
#include "engine/vk/pipeline.h"

#include "shaders/impostor_vert.spv.h"
#include "shaders/plant_vert.spv.h"
#include "shaders/raytraced_origin_impostor_frag.spv.h"
#include "shaders/raytraced_origin_plant_frag.spv.h"
#include "shaders/raytraced_origin_terrain_frag.spv.h"
#include "shaders/terrain_vert.spv.h"

namespace pf {

RaytracedOriginsPass createRaytracedOriginsPass(GpuResources& owner, VkPipelineLayout layout) {
    GpuResources modules(owner.ctx());
    const VkShaderModule plant = createShaderModule(modules, spirv_plant_vert);
    const VkShaderModule plantOrigin = createShaderModule(modules, spirv_raytraced_origin_plant_frag);
    GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.colorFormat = kRaytracedOriginFormat;
    desc.depthFormat = VK_FORMAT_D32_SFLOAT;
    auto make = [&](VkShaderModule vertex, VkShaderModule fragment, VkCullModeFlags cull) {
        desc.vertex = vertex;
        desc.fragment = fragment;
        desc.cullMode = cull;
        return createGraphicsPipeline(owner, desc);
    };
    // Culled as the colour pass culls them, so each pixel's origin is of the
    // surface it will show; of the impostors only those the sun's map could
    // reach (the rest are lit with their baked shadows).
    RaytracedOriginsPass pass;
    pass.pipelines.bark = make(plant, plantOrigin, VK_CULL_MODE_BACK_BIT);
    pass.pipelines.foliage = make(plant, plantOrigin, VK_CULL_MODE_NONE);
    pass.pipelines.impostors[0] = {make(createShaderModule(modules, spirv_impostor_vert),
                                        createShaderModule(modules, spirv_raytraced_origin_impostor_frag),
                                        VK_CULL_MODE_NONE),
                                   IMPOSTOR_PART_SHADOWED};
    pass.pipelines.terrain =
        make(createShaderModule(modules, spirv_terrain_vert),
             createShaderModule(modules, spirv_raytraced_origin_terrain_frag), VK_CULL_MODE_BACK_BIT);
    return pass;
}

void recordRaytracedOriginsPass(VkCommandBuffer cmd, const RaytracedOriginsPass& pass, const RaytracedSunImages& images,
                                const SurfaceGeometry& geometry, VkDescriptorSet set, const SurfaceLists& lists) {
    beginRaytracedOrigins(cmd, images);
    bindDrawSet(cmd, geometry.layout, set);
    pushFieldPass(cmd, geometry.layout, FIELD_PASS_COLOR);
    recordSurfaceDraws(cmd, geometry, pass.pipelines, lists);
    endRaytracedOrigins(cmd, images);
}

} // namespace pf
