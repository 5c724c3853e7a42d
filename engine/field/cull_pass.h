// The GPU-driven part of the field frame, its cull + LOD pass
// (docs/CULLING.md): one compute invocation per field instance tests the
// instance's bounding sphere against the frustum, picks its LOD from projected
// height with hysteresis (and a dithered fade between LODs), and appends it to
// the compacted visible list of its (model, LOD); a second small pass turns
// every non-empty list into a VkDrawIndexedIndirectCommand of its draw class
// and counts them, for vkCmdDrawIndexedIndirectCount (or, without that
// feature, instanceCount is written into one command per template and all are
// drawn). No per-plant CPU work per frame. The per-plant work runs over the
// near chunks of a cluster pass (engine/field/cluster_pass.h), or over every
// plant.
#pragma once

#include "engine/field/cull_uniforms.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/resources.h"
#include "shaders/shared/field_layouts.h"

#include <array>
#include <span>
#include <vector>

namespace pf {

// What the pass decides per instance before build_draws.comp makes the draws.
enum class CullKind {
    Camera,        // cull.comp: frustum, LOD with hysteresis and fades (CullUniforms, a LOD state per instance)
    ShadowCasters, // shadow_cull.comp: the sun's casters of a box (ShadowCullUniforms, shadow_select.h; no state)
};

struct CullPassInputs {
    CullKind kind = CullKind::Camera;
    const Buffer* instances = nullptr; // gpu::FieldInstance[instanceCount], storage
    const Buffer* models = nullptr;    // gpu::PlantModel[modelCount], storage (lists filled)
    uint32_t instanceCount = 0;
    uint32_t modelCount = 0;
    std::span<const gpu::DrawTemplate> templates; // copied to the GPU at creation
    // The chunks of plants to cull each frame (ClusterPass::near, written
    // before recordCullPass); null: every plant, in chunks written once.
    const Buffer* near = nullptr;
};

// Each phase's buffers below are regions of CULL_PHASE_REGIONS: region 0
// for CULL_PHASE_ALL and CULL_PHASE_EARLY, region 1 for CULL_PHASE_LATE.
struct CullPass {
    ComputeSet set; // CULL_BINDING_*: the uniforms, the inputs' buffers and the storage buffers below; Camera: set 1
                    // is a depth pyramid's readSet (createDepthPyramidReadLayout)
    VkPipeline cullPipeline = VK_NULL_HANDLE;
    VkPipeline latePipeline = VK_NULL_HANDLE; // Camera: cull_late.comp
    VkPipeline buildDrawsPipeline = VK_NULL_HANDLE;

    Buffer uniforms;    // host-visible CullUniforms (ShadowCullUniforms for ShadowCasters)
    Buffer templates;   // DrawTemplate[]
    Buffer state;       // uint per instance: LOD state (field_layouts.h); one unused word for ShadowCasters
    Buffer counts;      // per region a uint per (model, LOD), then the plants the late phase found occluded
    Buffer visible;     // uint entries: LOD lists of every model (LOD_COUNT × instanceCount); a list's late entries
                        // follow its early ones
    Buffer commands;    // per region DrawCommand[DRAW_CLASS_COUNT × templateCount], class c's at c × templateCount
    Buffer drawCounts;  // per region uint[DRAW_CLASS_COUNT]
    Buffer allCommands; // per region DrawCommand[templateCount] in template order (fallback path)
    Buffer readback;    // host-visible copy of counts then drawCounts, written at the end of every recordCullPass
    Buffer allPlants;   // without CullPassInputs::near: every plant in chunks (near_chunks.glsl)
    VkBuffer near = VK_NULL_HANDLE; // the chunks culled: CullPassInputs::near or allPlants

    uint32_t instanceCount = 0;
    uint32_t modelCount = 0;
    uint32_t templateCount = 0;
    std::array<uint32_t, DRAW_CLASS_COUNT> templatesPerClass{};    // fallback: how many templates each class has
    std::array<uint32_t, DRAW_CLASS_COUNT> firstTemplateOfClass{}; // templates are sorted by class
};

// Templates must be sorted by draw class. Throws when there are more
// instances than FIELD_MAX_INSTANCES. What the pass creates is owned by `owner`.
CullPass createCullPass(GpuResources& owner, const CullPassInputs& inputs);

// Per frame, before record: the uniforms (makeCullUniforms, cull_uniforms.h)
// with counts.x and counts.y filled from the pass.
void setCullUniforms(const CullPass& pass, const gpu::CullUniforms& uniforms);
// The same for a CullKind::ShadowCasters pass (engine/field/shadow_casters.h makes them).
void setCullUniforms(const CullPass& pass, const gpu::ShadowCullUniforms& uniforms);

// Records one phase (CULL_PHASE_*; shadow casters: CULL_PHASE_ALL): clear
// counters (ALL and EARLY clear both regions), cull (or pick shadow casters),
// build draws, copy counters to readback, and the barriers that make the
// visible list readable by vertex shaders and the commands by indirect draws.
// CULL_PHASE_LATE reads `pyramid`, a depth pyramid's readSet built after the
// early phase's draws (and after EARLY in the same command buffer).
void recordCullPass(VkCommandBuffer cmd, const CullPass& pass, uint32_t phase = CULL_PHASE_ALL,
                    VkDescriptorSet pyramid = VK_NULL_HANDLE);

// Draws every command of one class that a phase made: vkCmdDrawIndexedIndirectCount
// when the device has it, otherwise vkCmdDrawIndexedIndirect over the class's
// templates (empty ones draw nothing). The caller binds pipeline, index buffer
// and descriptor sets.
void drawClassIndirect(VkCommandBuffer cmd, const GpuContext& ctx, const CullPass& pass, uint32_t drawClass,
                       uint32_t phase = CULL_PHASE_ALL);

// Counters of the last recorded frame (read after its fence), both phases summed.
struct CullCounts {
    std::vector<uint32_t> perModelLod;                      // [model · LOD_COUNT + lod] entries in that list
    std::array<uint32_t, DRAW_CLASS_COUNT> drawsPerClass{}; // commands written
    std::array<uint32_t, LOD_COUNT> perLod{};               // summed over models (fading plants count in both)
    uint32_t occluded = 0; // in view and large enough to draw, hidden by the depth pyramid (the late phase)
};
CullCounts readCullCounts(const CullPass& pass);

} // namespace pf
