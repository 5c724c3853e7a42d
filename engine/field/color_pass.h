// The colour pass (docs/ARCHITECTURE.md, "The frame", step 3), the frame's
// "colour" scope: into the render target, the field's surfaces
// (surface_draws.h) from the cull pass's lists — or, for the naive
// baseline, every plant at full detail — with the far nodes' canopy, the
// terrain chunks in view and the sky; with occlusion culling in two
// renderings, the depth pyramid of the first and the cull pass's late phase
// against it recorded between them (docs/CULLING.md); the clouds' shadows
// and the clouds over all of it; then the anti-aliasing. Reads the draw
// sets of the cull pass's lists and of the naive list, the cluster pass's
// far nodes, the shadow map or the traced sun's visibility; writes the
// target (its depth pyramid too) and, with occlusion culling, the cull
// pass's late lists.
#pragma once

#include "engine/field/cloud_pass.h"
#include "engine/field/cloud_shadow_pass.h"
#include "engine/field/draw_sets.h"
#include "engine/field/surface_draws.h"
#include "engine/vk/render_target.h"

#include <optional>

namespace pf {

struct GpuTimer;

struct ColorPassInputs {
    const DrawTable* table = nullptr;
    const Buffer* lists = nullptr;           // the cull pass's visible lists
    const Buffer* naiveList = nullptr;       // every plant once (naiveVisibleList)
    const Buffer* frame = nullptr;           // the frame block the clouds read (FrameUniforms first)
    const Buffer* terrainVertices = nullptr; // the clouds' shadows draw the terrain again
    const Scene* scene = nullptr;            // its clouds and sun
    Antialiasing antialiasing;               // the target's (supportedAntialiasing)
};

// What a frame's colour pass draws, set by setColourView.
struct ColorView {
    glm::mat4 viewProj{1.0f}; // the camera's
    glm::vec3 camera{0.0f};
    glm::vec3 forward{0.0f};     // unit
    float pixelsPerMetre = 0.0f; // the camera's at one metre (CullUniforms::camera.w)
    float time = 0.0f;           // scene seconds
    // With sun shadows: the terrain chunks its square reaches are drawn with
    // the lookup, `shadowTexel` metres a texel.
    std::optional<glm::mat4> sunViewProj;
    float shadowTexel = 0.0f;
    bool canopy = false; // some leaf can be far (canopyCanBeDrawn): the canopy's draw is recorded
};

struct ColorPass {
    SurfacePipelines pipelines;
    VkDescriptorSet listsSet = VK_NULL_HANDLE; // the draw set of the cull pass's lists
    VkDescriptorSet naiveSet = VK_NULL_HANDLE; // of the naive list
    CloudPass clouds;                          // spheres 0 without clouds
    CloudShadowPass cloudShadows;              // map.width 0 without a cloud casting a shadow
    // setColourView: the terrain chunks drawn, with and without the shadow
    // lookup; whether the canopy is drawn; the clouds' wind drift.
    TerrainRanges terrain;
    bool drawCanopy = false;
    glm::vec3 cloudDrift{0.0f};
};

// What the pass creates is owned by `owner`.
ColorPass createColorPass(GpuResources& owner, const ColorPassInputs& inputs);

// Per frame, before record: `chunks` the drawn terrain's. Sorts the clouds'
// billboards into their host buffer, so call it while no frame is in flight.
void setColorView(ColorPass& pass, const Scene& scene, const TerrainChunks& chunks, const ColorView& view);

// What one frame's colour pass reads and writes besides the target.
struct ColorPassFrame {
    const SurfaceGeometry* geometry = nullptr;
    const CullPass* cull = nullptr;        // its lists drawn; with `occlusion` its late phase recorded inside
    const ClusterPass* clusters = nullptr; // the camera's cut: its far nodes as canopy; null without clusters
    bool occlusion = false;                // two renderings, the late phase between them
    bool naive = false;                    // the baseline: every plant at full detail, no canopy
};

// Into a target made with the inputs' anti-aliasing; leaves target.color in
// TRANSFER_SRC_OPTIMAL. With a timer, the scope "colour" and every scope
// nested in it (field_scopes.h), the late ones empty without occlusion.
void recordColorPass(VkCommandBuffer cmd, const ColorPass& pass, const ColorPassFrame& frame,
                     const RenderTarget& target, GpuTimer* timer);

} // namespace pf
