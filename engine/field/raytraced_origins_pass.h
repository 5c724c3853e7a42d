// The traced sun's origins pass (raytraced_sun_pass.h; docs/RAYTRACING.md,
// "Ray-traced sun shadows"), the first of its two steps in the frame's
// "shadow" scope: what the colour pass will show of the plant meshes (the
// cull pass's lists, or every plant at full detail for the naive
// baseline), the impostors the sun's square reaches and the terrain chunks
// it shadows, drawn once more (surface_draws.h) with the colour pass's view
// and culling, each pixel writing where its ray starts. Reads the draw set
// of the colour pass's lists and its terrain ranges, writes the traced
// sun's origins and depth; the trace (recordTracedSun) follows it.
#pragma once

#include "engine/field/raytraced_sun_pass.h"
#include "engine/field/surface_draws.h"

namespace pf {

struct RaytracedOriginsPass {
    SurfacePipelines pipelines; // traced_origin_*.frag behind the colour pass's vertex shaders
};

// `layout` the draw table's; the pipelines are owned by `owner`.
RaytracedOriginsPass createRaytracedOriginsPass(GpuResources& owner, VkPipelineLayout layout);

// `set` the draw set of the lists drawn, `lists` the colour pass's lists
// and terrain (SurfaceLists::plants null for the naive baseline).
void recordRaytracedOriginsPass(VkCommandBuffer cmd, const RaytracedOriginsPass& pass, const RaytracedSunImages& images,
                                const SurfaceGeometry& geometry, VkDescriptorSet set, const SurfaceLists& lists);

} // namespace pf
