// Ray-traced sun shadows (docs/RAYTRACING.md, "Ray-traced sun shadows"):
// exact shadows of the plants, one ray a pixel, in place of the shadow map.
// Three steps a frame. The origins pass draws what the colour pass will
// show of the plant meshes and the shadowed terrain chunks once more, each
// pixel writing where its ray starts (shaders/traced_origin_*.frag). The
// trace (shaders/raytraced_sun.comp) sends each ray towards the sun through
// the field's graph (engine/raytrace/field_graph.h), ending at the first hit
// (Robbins 1998, "Branching Shadows", ends shadow rays so), and writes the
// pixel's visibility. The colour pass reads it at its fragment
// (sunVisibilityOf, shaders/field_common.glsl). The graph holds the plants
// at rest, and the rays start from the rest pose of what they light: a
// swaying plant carries the shadows it has at rest.
#pragma once

#include "engine/raytrace/gpu_graph.h"
#include "engine/raytrace/raytrace_pass.h"
#include "engine/scene/field_content.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/resources.h"
#include "lsystem/common/memory_budget.h"

#include <glm/glm.hpp>

#include <memory>
#include <span>

namespace pf {

constexpr VkFormat kRaytracedOriginFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// The images of one frame size.
struct RaytracedSunImages {
    std::unique_ptr<GpuResources> resources;
    Image origins;    // the origins pass's colour: xyz where the ray starts, w 1 (0: no ray); then read by the trace
    Image depth;      // the origins pass's own
    Image visibility; // r32f: 1 lit, 0 in shadow; written by the trace, sampled by the colour pass
    VkExtent2D extent{};
};

struct RaytracedSunPass {
    GpuGraphBuffers graph;
    ComputeSet set; // the graph, origins and visibility; TracedSunPush
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE; // nearest: the colour pass fetches its own pixel
    RaytracedSunImages images;
    float rayLength = 0.0f; // metres: across the whole field
};

// A renderer that does not trace: no graph, images of one texel whose
// visibility the colour pass samples as 1. Owned by `owner`.
RaytracedSunPass createRaytracedSunPlaceholder(GpuResources& owner);
// Packs and uploads the graph of `content`'s plants (`plants`, its
// fieldInstancesOf), the graph's host memory checked against `memory`
// first (lsys::need); its rays reach across the whole field. Owned by
// `owner`. Its images are of one texel until the first resizeTracedSunImages.
RaytracedSunPass createRaytracedSunPass(GpuResources& owner, const FieldContent& content,
                                        std::span<const gpu::FieldInstance> plants, const lsys::MemoryBudget& memory);

// The colour pass's entry of the pass's visibility (FIELD_BINDING_TRACED_SUN).
DescriptorBinding raytracedSunBinding(const RaytracedSunPass& pass, VkShaderStageFlags stages);

// Makes the pass's images for `extent` when its last frame was another size
// (only while no frame is in flight). True when they were made again: the
// colour pass's descriptor of the visibility must then be written again.
bool resizeRaytracedSunImages(const GpuContext& ctx, RaytracedSunPass& pass, VkExtent2D extent);

// The origins pass: after it, draw the surfaces with the traced_origin_*
// pipelines, the colour pass's view and viewport.
void beginRaytracedOrigins(VkCommandBuffer cmd, const RaytracedSunImages& images);
void endRaytracedOrigins(VkCommandBuffer cmd, const RaytracedSunImages& images);

// The trace, `sun` the unit direction towards the sun; leaves the
// visibility for the colour pass's fragment shaders.
void recordRaytracedSun(VkCommandBuffer cmd, const RaytracedSunPass& pass, const glm::vec3& sun);

} // namespace pf
