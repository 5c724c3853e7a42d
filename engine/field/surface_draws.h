// The field's surfaces drawn in one sequence, by every pass that draws
// them: plants (bark, then foliage), impostors, the far nodes' canopy, the
// terrain and the sky, each step with the pass's own pipeline or left out
// where the pass has none. The colour pass draws all of them, the traced
// sun's origins pass the plants, the impostors the shadow map may reach and
// the shadowed terrain, the shadow passes the plants and impostors from the
// sun. The draws come from a pass's visible lists — the cull pass's for one
// phase, or a shadow-caster pass's — or, for the naive baseline, from every
// plant at full detail, one vkCmdDrawIndexed per plant and class.
#pragma once

#include "engine/field/cluster_pass.h"
#include "engine/field/cull_pass.h"
#include "engine/scene/field_content.h"
#include "engine/scene/terrain_chunks.h"

#include <array>

namespace pf {

struct GpuTimer;

// What the draws read besides their lists: the device's indirect draw
// features, the draw set's layout (push constants), the index pools, and
// for the naive draws every plant and its model's meshes.
struct SurfaceGeometry {
    const GpuContext* ctx = nullptr;
    VkPipelineLayout layout = VK_NULL_HANDLE; // DrawTable::layout
    const Buffer* indices = nullptr;          // plant meshes and billboards
    const Buffer* terrainIndices = nullptr;   // the terrain's chunks
    const Buffer* canopyIndices = nullptr;    // one far node's mesh (with clusters)
    const FieldContent* content = nullptr;    // the naive draws
};

// The impostor list drawn as one part (shaders/shared/sunlit_select.h) with its
// pipeline: IMPOSTOR_PART_NONE draws the whole list under the pass's push.
struct ImpostorDraw {
    VkPipeline pipeline = VK_NULL_HANDLE;
    uint32_t part = IMPOSTOR_PART_NONE;
};

// A pass's pipeline for each step; VK_NULL_HANDLE leaves the step out.
struct SurfacePipelines {
    uint32_t pass = FIELD_PASS_COLOR; // FieldPush::shadowPass, pushed by the pass before the draws
    VkPipeline bark = VK_NULL_HANDLE;
    VkPipeline foliage = VK_NULL_HANDLE; // the same as bark: bound once, each plant's bark and foliage together
    std::array<ImpostorDraw, 2> impostors{};
    VkPipeline canopy = VK_NULL_HANDLE;
    VkPipeline terrain = VK_NULL_HANDLE;       // the chunks the sun's map reaches (TerrainRanges::shadowed)
    VkPipeline sunlitTerrain = VK_NULL_HANDLE; // the others (TerrainRanges::sunlit)
    VkPipeline sky = VK_NULL_HANDLE;           // one triangle on the far plane
};

// Where the draws come from.
struct SurfaceLists {
    // The lists of a cull pass (the camera's, or a shadow-caster pass's) for
    // `phase`; null: every plant at full detail and no impostor (naive).
    const CullPass* plants = nullptr;
    uint32_t phase = CULL_PHASE_ALL;
    const ClusterPass* far = nullptr;       // its far nodes drawn as canopy; null: no canopy
    const TerrainRanges* terrain = nullptr; // the chunks drawn, then the sky; null: neither
};

// Inside a rendering, the draw set bound and the pass pushed. With a timer,
// the scopes plants, impostors, canopy and terrain_sky, every step's whether
// it draws or not (field_scopes.h).
void recordSurfaceDraws(VkCommandBuffer cmd, const SurfaceGeometry& geometry, const SurfacePipelines& pipelines,
                        const SurfaceLists& lists, GpuTimer* timer = nullptr);

} // namespace pf
