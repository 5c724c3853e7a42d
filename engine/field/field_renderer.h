// The GPU-driven field frame (docs/ARCHITECTURE.md, "The frame"): every
// plant in one instance buffer; per frame the cluster and cull passes pick
// what is drawn at which LOD and write the indirect draws, and the shadow
// passes (or the traced sun's) and the colour pass draw from those lists.
// The renderer owns the field's geometry and its passes and orders them:
// record() is the frame's list of passes. The CPU does no per-plant work per
// frame. recordNaive() draws the same field the simple way (every plant at
// full detail, one draw call each) as the baseline plantbench compares
// against.
#pragma once

#include "engine/field/cluster_pass.h"
#include "engine/field/color_pass.h"
#include "engine/field/cull_pass.h"
#include "engine/field/draw_sets.h"
#include "engine/field/field_clusters.h"
#include "engine/field/field_frame_stats.h"
#include "engine/field/field_geometry.h"
#include "engine/field/field_scopes.h"
#include "engine/field/field_uploads.h"
#include "engine/field/impostor_atlas.h"
#include "engine/field/raytraced_origins_pass.h"
#include "engine/field/raytraced_sun_pass.h"
#include "engine/field/shadow_cache.h"
#include "engine/field/shadow_map.h"
#include "engine/field/shadow_pass.h"
#include "engine/field/sun_shadows.h"
#include "engine/field/surface_draws.h"
#include "engine/physics/field_motion.h"
#include "engine/scene/camera.h"
#include "engine/scene/field_content.h"
#include "engine/vk/render_target.h"

#include <memory>
#include <optional>

namespace pf {

struct GpuTimer;

struct FieldRenderSettings {
    Antialiasing antialiasing; // FXAA unless set (antialiasing.h)
    SunShadows shadows = SunShadows::map;
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
    const ClusterTree& clusterTree() const { return clusters_.tree; } // empty without clusters
    const FieldRenderSettings& settings() const { return settings_; }
    // The settings' anti-aliasing as the device supports it
    // (supportedAntialiasing): make render targets with it.
    const Antialiasing& antialiasing() const { return settings_.antialiasing; }
    // What recordNaive draws in its colour pass.
    uint64_t naiveTriangles() const { return pf::naiveTriangles(content_); }
    uint32_t simulatedJoints() const { return motion_.pass.jointCount; } // shared copies and near plants' own
    VkDeviceSize gpuBytes() const; // device memory this renderer and its passes hold

private:
    const GpuContext& ctx_;
    FieldContent content_;
    SceneBox fieldBox_; // of content_: every frame's depth range holds it
    FieldRenderSettings settings_;
    GpuResources resources_; // everything below is created into it

    Buffer uniforms_; // the frame block: FrameUniforms, then FieldFrame (setView)
    FieldGeometry geometry_;
    FieldPlantBuffers plants_;
    FieldClusters clusters_; // empty without clusters
    FieldMotion motion_;
    ShadowMap shadowMap_;
    RaytracedSunPass raytracedSun_; // without ray-traced shadows: no graph, a visibility of one texel, 1
    ClusterPass cameraClusters_;    // with clusters: the camera's cut, whose near leaves the cull runs over
    CullPass cull_;                 // the camera's lists
    DrawTable drawTable_;
    ColorPass color_;
    ShadowPass shadows_;                    // its casters' passes are made (and cost memory) whatever the shadows
    RaytracedOriginsPass raytracedOrigins_; // with ray-traced shadows

    // A field with no plant has no quadtree to cut: its terrain and sky are drawn without one.
    bool clustered() const { return settings_.clusters.enabled && !content_.plants.empty(); }
    SurfaceGeometry surfaceGeometry() const;
    void recordSunShadows(VkCommandBuffer cmd, bool naive) const;
    void recordColor(VkCommandBuffer cmd, const RenderTarget& target, bool naive, GpuTimer* timer) const;
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
