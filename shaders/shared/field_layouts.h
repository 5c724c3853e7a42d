// GPU data layouts of the plant field (docs/ARCHITECTURE.md), shared by GLSL and C++.
// Members are vec4/uvec4 (or plain uints where Vulkan fixes the layout), so
// std430 and C++ agree without padding rules.
#ifndef PLANTFIELD_SHADERS_FIELD_LAYOUTS_H
#define PLANTFIELD_SHADERS_FIELD_LAYOUTS_H

#include "layouts.h"

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#endif

// Levels of detail: full geometry, reduced geometry, billboard impostor.
// The mesh LODs come first; the impostor is the last (and LOD_IMPOSTOR is the
// number of mesh LODs).
#define LOD_FULL 0
#define LOD_REDUCED 1
#define LOD_IMPOSTOR 2
#define LOD_COUNT 3
// PlantModel::lists: component l < LOD_COUNT is the first visible-list entry
// of LOD l, this one the model's instance count (every list's capacity).
#define PLANT_MODEL_LIST_CAPACITY LOD_COUNT

// Draw classes: each has its own pipeline and its own indirect command list.
#define DRAW_BARK 0     // opaque, back faces culled
#define DRAW_FOLIAGE 1  // alpha-tested, two-sided (leaves, petals, needles, grass)
#define DRAW_IMPOSTOR 2 // billboards sampling the impostor atlas
#define DRAW_CLASS_COUNT 3

// FieldVertex::albedo.a: how the fragment shader treats the surface.
#define SURFACE_BARK 0.0  // opaque, bark streaks
#define SURFACE_LEAF 1.0  // alpha-tested leaf card: uv in [0,1]², leaf outline cut by the shader
#define SURFACE_BLADE 2.0 // opaque two-sided thin blade or petal, no cut-out

// A visible-list entry: instance index in the low bits, then one bit that
// says the entry is fading in (rather than out), then its coverage.
#define VISIBLE_INDEX_BITS 24
#define VISIBLE_INDEX_MASK 0xFFFFFFu
#define VISIBLE_FADE_IN_BIT 0x1000000u
#define VISIBLE_COVERAGE_SHIFT 25 // 7 bits: 127 = fully drawn
#define VISIBLE_COVERAGE_MAX 127u
#define FIELD_MAX_INSTANCES (1u << VISIBLE_INDEX_BITS)

// Per-instance LOD state: current LOD in bits 0-1, the LOD it fades from in
// bits 2-3, fade progress 0..255 in bits 8-15 (255: settled, nothing to fade),
// and bit 16 set when the plant was drawn in the previous frame (occlusion
// culling: the early phase draws those again, docs/CULLING.md).
#define LOD_STATE_LOD_BITS 2u
#define LOD_STATE_LOD_MASK 3u
#define LOD_STATE_PROGRESS_SHIFT 8u
#define LOD_STATE_SETTLED 255u
#define LOD_STATE_VISIBLE_BIT 0x10000u

// The phases of the camera's cull (CullPush::phase). Without occlusion
// culling one phase draws every plant in view; with it the early phase draws
// the plants drawn last frame and the late phase, after the depth pyramid is
// built from what the early phase drew, the other plants the pyramid does not
// hide. Each phase has its own region of counters, commands and draw counts.
#define CULL_PHASE_ALL 0u
#define CULL_PHASE_EARLY 1u
#define CULL_PHASE_LATE 2u
#define CULL_PHASE_REGIONS 2u // ALL and EARLY share region 0, LATE has region 1

#define CULL_GROUP_SIZE 64

// Descriptor bindings of the field's draw set (set 0).
#define FIELD_BINDING_FRAME BINDING_FRAME_UNIFORMS // FrameUniforms (layouts.h) + FieldFrame
#define FIELD_BINDING_INSTANCES 1                  // FieldInstance[]
#define FIELD_BINDING_VISIBLE 2                    // uint[] visible entries, per (model, LOD) list
#define FIELD_BINDING_VERTICES 3                   // FieldVertex[]
#define FIELD_BINDING_MODELS 4                     // PlantModel[]
#define FIELD_BINDING_ATLAS_COLOR 5                // sampler2DArray: impostor albedo (rgb) + coverage (a)
#define FIELD_BINDING_ATLAS_NORMAL 6               // sampler2DArray: impostor normal (rgb·0.5+0.5) + depth (a)
#define FIELD_BINDING_SHADOW 7                     // sampler2DShadow: the sun's shadow map
#define FIELD_BINDING_TERRAIN 8                    // TerrainVertex[]
#define FIELD_BINDING_SKELETONS 9                  // Skeleton[] (physics_layouts.h)
#define FIELD_BINDING_POSES 10                     // JointPose[] of every simulated joint
#define FIELD_BINDING_INSTANCE_SKELETON 11         // uint per instance: the Skeleton its vertices follow
#define FIELD_BINDING_IMPOSTOR_OUTLINES 12         // per atlas layer, OUTLINE_CORNERS uv corners, two a texel
#define FIELD_BINDING_CLUSTER_NODES 13             // ClusterNode[] (cluster_layouts.h)
#define FIELD_BINDING_CANOPY 14                    // CanopyCell[] per node, CANOPY_CELLS each
#define FIELD_BINDING_CANOPY_FAR 15                // uint: the camera's far nodes (the canopy's instances)
#define FIELD_BINDING_IMPOSTOR_SHADOW 16           // sampler2DArray: impostor shadow frames, coverage (r)
#define FIELD_BINDING_RAYTRACED_SUN 17             // sampler2D: per pixel, the traced sun's visibility (r)

// FieldFrame::viewport.w: where the sun's visibility comes from.
#define FIELD_SUN_UNSHADOWED 0.0 // nowhere: every surface facing the sun is lit
#define FIELD_SUN_SHADOW_MAP 1.0 // the shadow map (shadow_map.h)
#define FIELD_SUN_RAYTRACED 2.0  // per pixel, a ray to the sun (engine/field/raytraced_sun_pass.h)

// Descriptor binding of the impostor bake (its own set 0).
#define IMPOSTOR_BAKE_BINDING_VERTICES 0 // FieldVertex[]

// Corners of the polygon a billboard quad is drawn as (engine/field/impostor_outline.h).
#define OUTLINE_CORNERS 4

// Texels of 16 bytes (R32G32B32A32_UINT views) each struct below takes in
// the texel views the draw shaders read it through: the stride they index by.
#define FIELD_INSTANCE_TEXELS 3
#define PLANT_MODEL_TEXELS 7
#define FIELD_VERTEX_TEXELS 4
#define TERRAIN_VERTEX_TEXELS 2
#define IMPOSTOR_OUTLINE_TEXELS (OUTLINE_CORNERS / 2) // per atlas layer: two uv corners a texel
#define CLUSTER_NODE_TEXELS 5

// Descriptor bindings of the cull pass (its own set 0).
#define CULL_BINDING_UNIFORMS 0     // CullUniforms
#define CULL_BINDING_INSTANCES 1    // FieldInstance[]
#define CULL_BINDING_MODELS 2       // PlantModel[]
#define CULL_BINDING_STATE 3        // uint[] per-instance LOD state
#define CULL_BINDING_COUNTS 4       // uint[] per (model, LOD): entries written this frame
#define CULL_BINDING_VISIBLE 5      // uint[] visible entries
#define CULL_BINDING_TEMPLATES 6    // DrawTemplate[]
#define CULL_BINDING_COMMANDS 7     // DrawCommand[] compacted, DRAW_CLASS_COUNT regions
#define CULL_BINDING_DRAW_COUNTS 8  // uint[DRAW_CLASS_COUNT]
#define CULL_BINDING_ALL_COMMANDS 9 // DrawCommand[] one per template, for the no-count fallback
#define CULL_BINDING_NEAR 10        // the chunks of plants to cull (cluster_layouts.h, near_chunks.glsl)
// The late phase reads the depth pyramid through a set of its own (set 1,
// engine/vk/depth_pyramid.h), made with every render target.
#define CULL_SET_PYRAMID 1

// One plant of the field: 48 bytes, so a million fit in 48 MB.
struct FieldInstance {
    vec4 positionScale; // xyz base on the terrain (m), w uniform scale
    vec4 orientation;   // x yaw about +y (radians), y wind phase (radians), zw 0
    uvec4 ids;          // x model (PlantModel index), y species, z variant, w 0
};

// One species variant: its meshes, bounds and LOD settings.
struct PlantModel {
    vec4 sphere; // bounding sphere in plant space: xyz centre, w radius (m, before instance scale)
    vec4 boxMin; // plant-space bounds, w 0
    vec4 boxMax; // w: not drawn at all below this many pixels of projected height (0: always drawn)
    vec4 lod; // x: LOD0→1 below this many pixels of projected height, y: LOD1→2 below, z: hysteresis fraction, w: fade
              // seconds
    uvec4 lists;    // first visible-list entry of each LOD, then the capacity (PLANT_MODEL_LIST_CAPACITY)
    uvec4 impostor; // x: first colour layer (ring r, frame f at x + r·y + f), y: frames around the plant, z: quads per
                    // billboard (1, 2, 3), w: first shadow frame layer
    vec4 impostorQuad; // x: half width (m), y: bottom, z: top (plant space), w: half depth of the baked box
};

// One mesh vertex in plant space: 64 bytes.
struct FieldVertex {
    vec4 position; // xyz plant space (m), w texture u
    vec4 normal;   // xyz unit normal, w texture v
    vec4 albedo;   // rgb linear albedo, a SURFACE_* kind
    uvec4 joint;   // x joint index in the model's skeleton, yzw 0
};

struct TerrainVertex {
    vec4 position; // xyz world (m), w 0
    vec4 normal;   // xyz unit, w 0
};

// The draw the build-draws pass turns into a command for each (model, LOD,
// class) that has a mesh.
struct DrawTemplate {
    uvec4 mesh; // x index count, y first index, z vertex offset, w draw class
    uvec4 list; // x counter slot = model·LOD_COUNT + LOD, y first visible entry, zw 0
};

// VkDrawIndexedIndirectCommand, as the GPU writes it (20 bytes, std430).
struct DrawCommand {
    uint indexCount;
    uint instanceCount;
    uint firstIndex;
    uint vertexOffset; // int in Vulkan; only ever non-negative here
    uint firstInstance;
};

// Bound as a read-only storage buffer, not a uniform block (docs/ARCHITECTURE.md,
// "What a shader may branch on").
struct CullUniforms {
    vec4 frustum[6]; // world-space planes, xyz inward normal, w offset: inside when dot(n,p)+w >= 0
    vec4 camera;     // xyz position, w pixels per metre at one metre of distance (viewport height / (2 tan(fov/2)))
    uvec4 counts; // x instances, y templates, z forced LOD (0xFFFFFFFF: none), w 1 on the first frame (state is reset)
    vec4 timing;  // x seconds since the previous frame, yzw 0
    mat4 view;    // world → view space (x right, y up, looking down −z): the late phase's occlusion test
    vec4 projection; // x P[0][0], y P[1][1], z P[2][2], w P[3][2] of the camera's projection (depth 0 near, 1 far)
    vec4 viewport;   // x width, y height (pixels), z near plane (m), w depth pyramid levels
};

// Push constants of cull.comp, cull_late.comp and build_draws.comp.
struct CullPush {
    uvec4 phase; // x CULL_PHASE_*, y counters of one region (models · LOD_COUNT), zw 0
};

// The shadow-caster pass (shadow_cull.comp, engine/field/shadow_casters.h):
// one invocation per instance picks the plants whose bounding sphere meets
// the sun's box, split between the cached map of static casters and the
// casters drawn every frame on top of it (shadow_select.h). counts sits where
// CullUniforms has it: build_draws.comp reads counts.y of either.
#define SHADOW_CULL_CACHE 0u // the plants the cache holds
#define SHADOW_CULL_FRAME 1u // every other caster, at the LOD the camera sees it at
// Bound as a read-only storage buffer, not a uniform block (docs/ARCHITECTURE.md,
// "What a shader may branch on").
struct ShadowCullUniforms {
    vec4 box[6];      // planes of the sun's box (frustumPlanes of its view-projection), as CullUniforms::frustum
    vec4 camera;      // xyz the camera, w its pixels per metre at one metre (CullUniforms::camera)
    uvec4 counts;     // x instances, y templates, z forced LOD (LOD_NOT_FORCED: none), w SHADOW_CULL_CACHE or _FRAME
    vec4 cacheCamera; // xyz where the camera stood when the cache was drawn, w how far it may move from there (m)
    vec4 cachePixels; // x the fewest, y the most pixels per metre at one metre the cache serves; zw 0
    vec4 view[6];     // the camera's frustum planes (SHADOW_CULL_FRAME: casters whose shadow may fall in view)
    vec4 sun;         // xyz unit vector toward the sun, w 0
};

// The push constants of one impostor bake frame (engine/field/impostor_atlas.h):
// an orthographic view fitted to the model's box. Each axis maps plant
// space to [-1, 1] about the frame's centre c: xyz = axis / half extent,
// w = -dot(c, axis) / half extent.
struct ImpostorBakePush {
    vec4 right;  // the frame's right axis: image column, u 0 → 1
    vec4 up;     // its up axis: image row 0 at +1
    vec4 toView; // toward the viewer: depth 0 at +1 (the front), 1 at -1
};

// The field's draw push constants (field_common.glsl fieldPush). shadowPass:
// which view the vertex shaders project into.
#define FIELD_PASS_COLOR 0u        // the camera's
#define FIELD_PASS_SHADOW 1u       // the sun's, into the frame's shadow map (FieldFrame::sunViewProj)
#define FIELD_PASS_SHADOW_CACHE 2u // the sun's, into the cache of static casters (FieldFrame::sunCacheViewProj)
// impostorPart: which of the listed impostors a colour draw of impostor.vert
// keeps (the others collapse to a point there): only those the frame's
// shadow map may reach, or only those it cannot reach, drawn by a pipeline
// with no shadow lookup (sunlit_select.h). Draws of anything else push
// IMPOSTOR_PART_NONE.
#define IMPOSTOR_PART_NONE 0u
#define IMPOSTOR_PART_SHADOWED 1u
#define IMPOSTOR_PART_SUNLIT 2u

struct FieldPush {
    uint shadowPass;   // FIELD_PASS_*
    uint impostorPart; // IMPOSTOR_PART_*
};

// Field additions to the frame uniforms (after FrameUniforms in the same block).
struct FieldFrame {
    mat4 sunViewProj;      // world → shadow map clip space
    mat4 sunCacheViewProj; // world → the shadow cache's clip space (the frame's map is a window of it)
    vec4 viewport;         // x width, y height (pixels), z shadow map texel size (m), w FIELD_SUN_*
    vec4 wind;             // xz direction × speed (m/s), y gust strength, w time (s)
    vec4 windDetail; // x turbulence, y gust wavelength (m), z gust front speed (m/s), w impostor sway (m per m/s of
                     // gust, at the top)
};

#ifdef __cplusplus
} // namespace gpu
static_assert(LOD_COUNT <= 3, "PlantModel::lists holds one first entry per LOD and the capacity in a uvec4");
static_assert(LOD_COUNT <= (1u << LOD_STATE_LOD_BITS) && LOD_STATE_LOD_MASK == (1u << LOD_STATE_LOD_BITS) - 1u);
static_assert(sizeof(gpu::FieldInstance) == FIELD_INSTANCE_TEXELS * 16);
static_assert(sizeof(gpu::PlantModel) == PLANT_MODEL_TEXELS * 16);
static_assert(sizeof(gpu::FieldVertex) == FIELD_VERTEX_TEXELS * 16);
static_assert(sizeof(gpu::TerrainVertex) == TERRAIN_VERTEX_TEXELS * 16);
static_assert(sizeof(gpu::DrawTemplate) == 32);
static_assert(sizeof(gpu::DrawCommand) == 20);
static_assert(sizeof(gpu::CullUniforms) == 15 * 16);
static_assert(sizeof(gpu::CullPush) == 16);
static_assert(sizeof(gpu::FieldPush) == 8);
static_assert(sizeof(gpu::ShadowCullUniforms) == 17 * 16);
static_assert(offsetof(gpu::ShadowCullUniforms, counts) == offsetof(gpu::CullUniforms, counts));
static_assert(sizeof(gpu::FieldFrame) == 2 * 64 + 3 * 16);
static_assert(sizeof(gpu::ImpostorBakePush) == 3 * 16);
#endif

#endif
