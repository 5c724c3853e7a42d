#include "engine/field/color_pass.h"

#include "engine/field/field_scopes.h"
#include "engine/vk/depth_pyramid.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"

#include "shaders/canopy_frag.spv.h"
#include "shaders/canopy_vert.spv.h"
#include "shaders/impostor_frag.spv.h"
#include "shaders/impostor_sunlit_frag.spv.h"
#include "shaders/impostor_vert.spv.h"
#include "shaders/plant_frag.spv.h"
#include "shaders/plant_vert.spv.h"
#include "shaders/sky_frag.spv.h"
#include "shaders/sky_vert.spv.h"
#include "shaders/terrain_frag.spv.h"
#include "shaders/terrain_sunlit_frag.spv.h"
#include "shaders/terrain_vert.spv.h"

namespace pf {
namespace {

SurfacePipelines createColorPipelines(GpuResources& owner, VkPipelineLayout layout, VkSampleCountFlagBits samples) {
    GpuResources modules(owner.ctx());
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

    GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = samples;
    auto make = [&](const Stages& s, VkCullModeFlags cull) {
        desc.vertex = s.vertex;
        desc.fragment = s.fragment;
        desc.cullMode = cull;
        return createGraphicsPipeline(owner, desc);
    };
    SurfacePipelines p;
    p.pass = FIELD_PASS_COLOR;
    // The sky lies on the far plane (depth 1, the clear value): drawn last,
    // it fills what nothing else covered, and writes no depth.
    desc.depthWrite = false;
    p.sky = make(sky, VK_CULL_MODE_NONE);
    desc.depthWrite = true;
    p.terrain = make(terrain, VK_CULL_MODE_BACK_BIT);
    p.sunlitTerrain = make(sunlitTerrain, VK_CULL_MODE_BACK_BIT);
    p.bark = make(plant, VK_CULL_MODE_BACK_BIT);
    p.foliage = make(plant, VK_CULL_MODE_NONE); // leaves are seen from both sides
    p.impostors = {{{make(impostor, VK_CULL_MODE_NONE), IMPOSTOR_PART_SHADOWED},
                    {make(sunlitImpostor, VK_CULL_MODE_NONE), IMPOSTOR_PART_SUNLIT}}};
    p.canopy = make(canopy, VK_CULL_MODE_NONE); // canopyMeshIndices: skirts last
    return p;
}

// Between the colour pass's two renderings: the depth pyramid of what the
// early phase drew (the terrain the main occluder), the late cull against
// it, and the plants it found visible drawn into the loaded colour and depth.
void recordLatePhase(VkCommandBuffer cmd, const ColorPass& pass, const ColorPassFrame& frame,
                     const RenderTarget& target, GpuTimer* timer) {
    vkCmdEndRendering(cmd);
    {
        TimedFieldScope scope(cmd, timer, FieldScope::depthPyramid);
        recordDepthPyramid(cmd, target.pyramid);
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::occlusion);
        recordCullPass(cmd, *frame.cull, CULL_PHASE_LATE, target.pyramid.readSet);
    }
    TimedFieldScope scope(cmd, timer, FieldScope::lateDraws);
    beginTargetPass(cmd, target, TargetPassPart::last);
    pushFieldPass(cmd, frame.geometry->layout, FIELD_PASS_COLOR);
    SurfaceLists late;
    late.plants = frame.cull;
    late.phase = CULL_PHASE_LATE;
    recordSurfaceDraws(cmd, *frame.geometry, pass.pipelines, late);
}

} // namespace

ColorPass createColorPass(GpuResources& owner, const ColorPassInputs& inputs) {
    ColorPass pass;
    const Buffer* lists[] = {inputs.lists, inputs.naiveList};
    const std::vector<VkDescriptorSet> sets = createDrawSets(owner, *inputs.table, lists);
    pass.listsSet = sets[0];
    pass.naiveSet = sets[1];
    const auto samples = VkSampleCountFlagBits(colorPassSamples(inputs.antialiasing));
    pass.pipelines = createColorPipelines(owner, inputs.table->layout, samples);
    const Scene& scene = *inputs.scene;
    pass.clouds = createCloudPass(owner, scene.clouds, *inputs.frame, samples);
    pass.cloudShadows = createCloudShadowPass(owner, scene.clouds, sunDirection(environmentOf(scene)), *inputs.frame,
                                              *inputs.terrainVertices, samples);
    return pass;
}

void setColorView(ColorPass& pass, const Scene& scene, const TerrainChunks& chunks, const ColorView& view) {
    setCloudView(pass.clouds, scene, view.time, view.camera, view.forward);
    pass.cloudDrift = meanWindVelocity(scene.wind) * view.time;
    // The shaders look the shadow up 1.5 texels along the normal (sunMapPosition).
    pass.terrain = visibleTerrainRanges(chunks, view.viewProj, view.camera, view.pixelsPerMetre, view.sunViewProj,
                                        2.0f * view.shadowTexel);
    pass.drawCanopy = view.canopy;
}

void recordColorPass(VkCommandBuffer cmd, const ColorPass& pass, const ColorPassFrame& frame,
                     const RenderTarget& target, GpuTimer* timer) {
    // The whole pass, anti-aliasing included, is one scope: tiling and CPU
    // rasterisers (lavapipe) shade at the end of the pass, so the draw scopes
    // inside it measure only their share of vertex work and binning there.
    // The FXAA pass (FieldScope::antialias) is a rendering of its own after it.
    TimedFieldScope color(cmd, timer, FieldScope::color);
    const bool twoParts = !frame.naive && frame.occlusion;
    const VkPipelineLayout layout = frame.geometry->layout;
    bindDrawSet(cmd, layout, frame.naive ? pass.naiveSet : pass.listsSet);
    beginTargetPass(cmd, target, twoParts ? TargetPassPart::first : TargetPassPart::whole);
    pushFieldPass(cmd, layout, FIELD_PASS_COLOR);
    SurfaceLists lists;
    if (!frame.naive) {
        lists.plants = frame.cull;
        lists.phase = twoParts ? CULL_PHASE_EARLY : CULL_PHASE_ALL;
        if (pass.drawCanopy) lists.far = frame.clusters;
    }
    lists.terrain = &pass.terrain;
    recordSurfaceDraws(cmd, *frame.geometry, pass.pipelines, lists, timer);
    if (twoParts) {
        recordLatePhase(cmd, pass, frame, target, timer);
    } else {
        // Every frame has the same scopes.
        for (FieldScope late : {FieldScope::depthPyramid, FieldScope::occlusion, FieldScope::lateDraws})
            TimedFieldScope scope(cmd, timer, late, ScopeStart::insideRendering);
    }
    {
        // Last, over everything opaque and the sky: their shadows on the
        // ground, then the clouds back to front.
        TimedFieldScope scope(cmd, timer, FieldScope::clouds, ScopeStart::insideRendering);
        recordCloudShadowPass(cmd, pass.cloudShadows, *frame.geometry->terrainIndices, pass.terrain, pass.cloudDrift);
        recordCloudPass(cmd, pass.clouds);
    }
    endTargetPass(cmd, target, timer);
}

} // namespace pf
