// The GPU-driven field frame (docs/ARCHITECTURE.md): every plant in one instance
// buffer; per frame the cull pass picks what is drawn at which LOD and
// writes the indirect draws, the shadow pass and the colour pass draw from
// those lists. The CPU does no per-plant work per frame. recordNaive() draws
// the same field the simple way (every plant at full detail, one draw call
// each) as the baseline plantbench compares against.
#pragma once

#include "engine/field/cloud_pass.h"
#include "engine/field/cloud_shadow_pass.h"
#include "engine/field/cluster_pass.h"
#include "engine/field/cull_pass.h"
#include "engine/field/field_scopes.h"
#include "engine/field/field_uploads.h"
#include "engine/field/impostor_atlas.h"
#include "engine/field/shadow_cache.h"
#include "engine/field/shadow_map.h"
#include "engine/field/sun_shadows.h"
#include "engine/field/traced_sun_pass.h"
#include "engine/physics/field_motion.h"
#include "engine/scene/camera.h"
#include "engine/scene/field_content.h"
#include "engine/scene/terrain_chunks.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/render_target.h"
#include "engine/vk/target_pass.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace pf {

struct GpuTimer;

// The field's hierarchy of clusters (docs/CLUSTERS.md).
struct ClusterSettings {
    bool enabled = true;    // false: every plant through the per-plant cull every frame (--no-clusters)
    float leafSide = 32.0f; // metres: leaves are the largest quadtree tiles of the terrain no wider than this
    // A node is drawn as its canopy where one canopy cell covers fewer pixels than this and its parent's does not.
    float thresholdPixels = 1.0f;
};

struct FieldRenderSettings {
    Antialiasing antialiasing; // FXAA unless set (antialiasing.h)
    SunShadows shadows = SunShadows::shadowMap;
    uint32_t shadowMapSize = 1024;
    float shadowRadius = 60.0f; // metres: half the side of the shadowed square ahead of the camera
    ShadowCacheSettings shadowCache;
    float impostorSway = 0.04f; // metres an impostor's top leans per m/s of gust (times the plant's scale)
    ImpostorSettings impostors;
    // Two-phase occlusion culling against the depth pyramid (docs/CULLING.md):
    // plants hidden behind the terrain and nearer plants are not drawn. Off
    // unless asked for: on lavapipe the pyramid, the second cull and the
    // second rendering cost more than the plants they hide (docs/BENCHMARKS.md,
    // 2026-12-02).
    bool occlusionCulling = false;
    ClusterSettings clusters;
    // The host memory of the uploads (fieldUploadBytes), checked before any of them.
    lsys::MemoryBudget memory = lsys::machineMemoryBudget();
};

struct FieldView {
    Camera camera;
    float time = 0.0f;                 // scene seconds
    float deltaTime = 0.0f;            // seconds since the previous frame (LOD fades advance by it)
    bool firstFrame = true;            // LOD state starts settled at each plant's target LOD
    std::optional<uint32_t> forcedLod; // every visible plant at this LOD (tests, debugging)
    std::optional<uint32_t> forcedCut; // CLUSTER_CUT_ALL_NEAR or _ALL_FAR in place of the threshold (tests)
    bool realTime = false;             // a window: physics steps as field_motion.h says for real time
};

// Names of the LODs and draw classes in statistics, reports and the overlay.
inline constexpr std::array<const char*, LOD_COUNT> kLodNames = {"full", "reduced", "impostor"};
inline constexpr std::array<const char*, DRAW_CLASS_COUNT> kDrawClassNames = {"bark", "foliage", "impostor"};

// What the last recorded frame drew, from the cull pass's counters.
struct FieldFrameStats {
    uint32_t instances = 0;
    std::array<uint32_t, LOD_COUNT> plantsPerLod{}; // fading plants count at both LODs
    std::array<uint32_t, DRAW_CLASS_COUNT> draws{}; // indirect commands per class
    uint64_t triangles = 0;                         // colour pass, plants and canopy
    uint32_t occluded =
        0; // in view and large enough to draw, hidden by the depth pyramid (0 without occlusion culling)
    // The sun's shadow map (zero without it): plants drawn into this
    // frame's map on top of the cache, per LOD; impostors the cache holds
    // (as last drawn); times this renderer has drawn the cache.
    std::array<uint32_t, LOD_COUNT> shadowCastersPerLod{};
    uint32_t shadowCacheCasters = 0;
    uint64_t shadowCacheRenders = 0;
    // The cut through the clusters (zero without clusters): nodes drawn as
    // canopy and their plants, leaves whose plants the per-plant cull ran
    // over and their plants; plants in neither were culled with their leaf.
    uint32_t clustersFar = 0, clusterFarPlants = 0;
    uint32_t nearLeaves = 0, nearPlants = 0;

    // Entries of every visible list: a fading plant counts twice.
    uint32_t visibleEntries() const;
    // Plants in no list and in no far node: not in view, too small to draw, or occluded.
    uint32_t culled() const;
};

// "full 3  reduced 40  impostor 900": plants per LOD, for logs and the overlay.
std::string plantsPerLodText(const FieldFrameStats& stats);

class FieldRenderer {
public:
    FieldRenderer(const GpuContext& ctx, FieldContent content, const FieldRenderSettings& settings);
    ~FieldRenderer();
    FieldRenderer(const FieldRenderer&) = delete;
    FieldRenderer& operator=(const FieldRenderer&) = delete;

    // Prepares the next frame: its uniforms and the plan of its physics
    // (advanceFieldMotion), nothing submitted. Call only while no frame is
    // in flight, once before each record.
    void setView(const FieldView& view, VkExtent2D extent);
    // Into a target made with antialiasing(). Leaves target.color in
    // TRANSFER_SRC_OPTIMAL. With a timer, writes one scope per entry of
    // kFieldScopes (field_scopes.h).
    void record(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer = nullptr) const;
    // The baseline: no culling, no LOD, one vkCmdDrawIndexed per plant and class.
    void recordNaive(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer = nullptr) const;
    // After the fence of a frame recorded with record().
    FieldFrameStats readStats() const;

    const GpuContext& context() const { return ctx_; }
    const FieldContent& content() const { return content_; }
    const ClusterTree& clusterTree() const { return clusterTree_; } // empty without clusters
    const FieldRenderSettings& settings() const { return settings_; }
    // The settings' anti-aliasing as the device supports it
    // (supportedAntialiasing): make render targets with it.
    const Antialiasing& antialiasing() const { return settings_.antialiasing; }
    uint64_t naiveTriangles() const;                                     // what recordNaive draws in its colour pass
    uint32_t simulatedJoints() const { return motion_.pass.jointCount; } // shared copies and near plants' own
    VkDeviceSize gpuBytes() const; // device memory this renderer and its passes hold

private:
    struct Pipelines {
        VkPipeline sky = VK_NULL_HANDLE, terrain = VK_NULL_HANDLE, sunlitTerrain = VK_NULL_HANDLE,
                   bark = VK_NULL_HANDLE, foliage = VK_NULL_HANDLE, impostor = VK_NULL_HANDLE,
                   sunlitImpostor = VK_NULL_HANDLE, canopy = VK_NULL_HANDLE, plantShadow = VK_NULL_HANDLE,
                   impostorShadow = VK_NULL_HANDLE, originBark = VK_NULL_HANDLE, originFoliage = VK_NULL_HANDLE,
                   originImpostor = VK_NULL_HANDLE, originTerrain = VK_NULL_HANDLE;
    };

    const GpuContext& ctx_;
    FieldContent content_;
    FieldRenderSettings settings_;
    GpuResources resources_; // everything below is created into it

    Buffer uniforms_;
    Buffer vertices_, indices_;
    Buffer models_, instances_;
    Buffer terrainVertices_, terrainIndices_;
    Buffer outlines_;                       // atlas_.outlines: the rectangle each atlas layer's billboards are drawn as
    Buffer naiveVisible_;                   // entry i = plant i at full coverage
    TerrainChunks terrainChunks_;           // the drawn terrain's chunks, in terrainIndices_
    TerrainRanges terrainRanges_;           // what this frame draws of them, with and without shadows (setView)
    Heightfield drawnTerrain_;              // the terrain as its mesh draws it
    std::array<MeshRange, 3> billboards_{}; // 1, 2, 3 quads
    ImpostorAtlas atlas_;
    ShadowMap shadow_;
    TracedSunPass tracedSun_; // without ray-traced shadows: no graph, a visibility of one texel, 1
    CullPass cull_;
    CullPass shadowCacheCasters_, shadowFrameCasters_; // CullKind::ShadowCasters: SHADOW_CULL_CACHE, _FRAME
    // With clusters: the quadtree, the camera's cut and the leaves meeting
    // the sun's boxes, whose plants the passes above run over.
    ClusterTree clusterTree_;
    Buffer clusterNodes_;
    Buffer canopy_, canopyIndices_; // every node's canopy (canopy.h), the mesh of one far node
    bool drawCanopy_ = false;       // setView: some leaf may be far this frame
    ClusterPass clusters_, shadowCacheClusters_, shadowFrameClusters_;
    FieldMotion motion_;
    CloudPass clouds_;             // spheres 0 without clouds
    CloudShadowPass cloudShadows_; // map.width 0 without a cloud casting a shadow
    glm::vec3 cloudDrift_{0.0f};   // setView: the clouds' wind drift at the frame's time

    // The shadow cache (setView): what it holds, whether this frame draws it
    // again, where the frame's map starts in it, how often it was drawn.
    ShadowView shadowCache_;
    bool drawShadowCache_ = false;
    glm::ivec2 shadowWindow_{0};
    uint64_t shadowCacheRenders_ = 0;

    VkDescriptorSet drawSet_ = VK_NULL_HANDLE;        // visible = the cull pass's lists
    VkDescriptorSet naiveSet_ = VK_NULL_HANDLE;       // visible = naiveVisible_
    VkDescriptorSet shadowCacheSet_ = VK_NULL_HANDLE; // visible = shadowCacheCasters_'s lists
    VkDescriptorSet shadowFrameSet_ = VK_NULL_HANDLE; // visible = shadowFrameCasters_'s lists
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    Pipelines pipelines_;

    void uploadGeometry();
    void uploadInstances();
    void createClusters(const std::vector<gpu::FieldInstance>& instances, const std::vector<gpu::PlantModel>& models);
    void createDescriptors();
    void createPipelines();
    void planShadows(const FieldView& view, const glm::vec3& sun, VkExtent2D extent, const glm::mat4& cameraViewProj,
                     gpu::FieldFrame& field);
    void setCasterUniforms(const CullPass& casters, const ClusterPass& clusters,
                           const gpu::ShadowCullUniforms& uniforms) const;
    void recordShadowCache(VkCommandBuffer cmd) const;
    void recordShadowPass(VkCommandBuffer cmd) const;
    void recordNaiveShadowPass(VkCommandBuffer cmd) const;
    void createTracedSun(const std::vector<gpu::FieldInstance>& instances);
    // The vertex shaders the origins pass shares with the colour pass.
    struct TracedOriginVertices {
        VkShaderModule plant, impostor, terrain;
    };
    void createTracedOriginPipelines(GraphicsPipelineDesc desc, const TracedOriginVertices& vertices);
    void sizeTracedSun(VkExtent2D extent);
    void recordTracedSunPass(VkCommandBuffer cmd, bool naive) const;
    void pushFieldPass(VkCommandBuffer cmd, uint32_t pass, uint32_t impostorPart = IMPOSTOR_PART_NONE) const;
    void drawShadowCasters(VkCommandBuffer cmd, const CullPass& casters, VkDescriptorSet set, uint32_t pass) const;
    void recordColourPass(VkCommandBuffer cmd, const RenderTarget& target, bool naive, GpuTimer* timer) const;
    void drawPlantLists(VkCommandBuffer cmd, uint32_t phase, GpuTimer* timer) const;
    void recordLatePhase(VkCommandBuffer cmd, const RenderTarget& target, GpuTimer* timer) const;
    bool occlusion() const { return settings_.occlusionCulling; }
    void drawPlantsNaive(VkCommandBuffer cmd, bool bark, bool foliage) const;
};

// Replaces a live renderer by one drawing `content` with its settings
// (plantfield --watch), between frames: call it where setView may be called.
// The new renderer is built first, so when that throws the old one is kept
// and still draws; the old one's destructor waits for the device before its
// resources go. Both are held on the GPU for that moment. What the next frame
// draws is what a fresh renderer of `content` draws (the view's firstFrame
// set, as for any renderer's first frame).
void replaceFieldContent(std::unique_ptr<FieldRenderer>& renderer, FieldContent content);

} // namespace pf
