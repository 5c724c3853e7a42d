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

#include "engine/vk/compute_set.h"
#include "engine/vk/resources.h"
#include "shaders/field_layouts.h"

#include <glm/glm.hpp>

#include <array>
#include <span>
#include <vector>

namespace pf {

// The six planes of a view-projection (Vulkan clip space, depth 0..1),
// normalised, normals pointing inward.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj);

// The visible-list layout the cull pass appends into: for each LOD l, for
// each model m in order, a region of (instances of m) entries, so
// lists[l] = l · instanceCount + (instances of models before m) and
// lists[PLANT_MODEL_LIST_CAPACITY] = instances of m, and no list can
// overflow. Fills lists of every model from the instances' ids.x; the
// visible buffer then holds LOD_COUNT · instanceCount entries. Throws when
// an instance names a model that does not exist.
void assignVisibleLists(std::span<gpu::PlantModel> models, std::span<const gpu::FieldInstance> instances);

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

// Pixels per metre at one metre of distance of a camera with this vertical
// field of view over this many pixels (CullUniforms::camera.w).
float pixelsPerMetre(float fovYRadians, uint32_t viewportHeight);

// Per frame, before record: frustum, camera, forced LOD, delta time.
// `firstFrame` resets every instance's LOD state to settled at its target LOD
// (and has the early phase draw nothing). counts.x and counts.y (instances,
// templates) are left 0: setCullUniforms fills them from the pass.
gpu::CullUniforms makeCullUniforms(const glm::mat4& viewProj, const glm::vec3& cameraPosition, float fovYRadians,
                                   uint32_t viewportHeight, float deltaSeconds, bool firstFrame,
                                   uint32_t forcedLod = 0xFFFFFFFFu);
// What the late phase's occlusion test needs (CullUniforms::view, projection,
// viewport): the camera's view and projection (perspectiveRH_ZO), the
// viewport, its near plane and the levels of its depth pyramid.
void setOcclusionUniforms(gpu::CullUniforms& uniforms, const glm::mat4& view, const glm::mat4& projection,
                          glm::uvec2 viewport, float nearPlane, uint32_t pyramidLevels);
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

// Every plant of a field in chunks of CULL_GROUP_SIZE, with the near list's
// header (cluster_layouts.h): what a cull pass without clusters runs over.
std::vector<uint32_t> allPlantChunks(uint32_t instanceCount, uint32_t maxGroupsPerRow);

// Counters of the last recorded frame (read after its fence), both phases summed.
struct CullCounts {
    std::vector<uint32_t> perModelLod;                      // [model · LOD_COUNT + lod] entries in that list
    std::array<uint32_t, DRAW_CLASS_COUNT> drawsPerClass{}; // commands written
    std::array<uint32_t, LOD_COUNT> perLod{};               // summed over models (fading plants count in both)
    uint32_t occluded = 0; // in view and large enough to draw, hidden by the depth pyramid (the late phase)
};
CullCounts readCullCounts(const CullPass& pass);

// The same decision on the CPU (the reference the tests check the GPU
// against): the LOD list entries instance i gets this frame, updating state.
struct CpuCullResult {
    std::vector<std::vector<uint32_t>> lists; // [model · LOD_COUNT + lod] visible entries, sorted
};
// A run of plants the cull goes over (one near leaf); `restart`: as on a first frame.
struct CpuNearRange {
    uint32_t first = 0, count = 0;
    bool restart = false;
};
CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state);
// Over these plants only (the others keep their state).
CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state,
                        std::span<const CpuNearRange> near);

// The late phase's occlusion test on the CPU (shaders/occlusion_test.h):
// true when the world-space sphere (xyz centre, w radius) lies behind every
// pixel of its screen rectangle in `pyramid` (depthPyramidOnCpu's levels),
// with the uniforms' view, projection and viewport.
bool sphereOccludedOnCpu(const glm::vec4& sphere, const gpu::CullUniforms& uniforms,
                         const std::vector<std::vector<float>>& pyramid);

} // namespace pf
