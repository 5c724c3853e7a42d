// Billboard impostors (LOD2, after Tankard 2001's billboards): at load, every plant
// model is rendered on the GPU from `frames` directions around its vertical
// axis on each of IMPOSTOR_RINGS rings of elevation into a layered atlas of
// albedo + coverage and normal + depth, so far plants are drawn as one quad
// turned to the view (showing the frame nearest the view's azimuth and
// elevation) or, seen from near the horizon, as two or three crossed quads,
// each showing the frame seen along its normal.
#pragma once

#include "engine/field/impostor_outline.h"
#include "engine/scene/plant_models.h"
#include "engine/vk/resources.h"

#include <vector>

namespace pf {

struct ImpostorSettings {
    uint32_t frameSize = 256; // pixels per side of one frame
    uint32_t frames = 12;     // views around the plant, 360/frames degrees apart (0°: looking along -z of plant space)
    // Pixels per side of one shadow frame: a 10 m tree spans about 85 texels
    // of the 1024² shadow map over 120 m, so 128 keeps every map texel
    // sampled from at least one frame texel, at a sixteenth of a colour
    // frame's memory (coverage and depth, two bytes a texel).
    uint32_t shadowFrameSize = 128;
};

// Frame convention (shaders/shared/impostor_frame.h has the axes and extents, for
// the bake and the billboards). Frame f of n on ring r views the plant from
// azimuth a = 2π·f/n about +y and elevation e = r·IMPOSTOR_RING_STEP: the
// orthographic camera sits along d = (sin a·cos e, sin e, cos a·cos e),
// looks along -d, its right axis is (cos a, 0, -sin a) and its up axis the
// vertical tilted away from d (frame 0 of ring 0 looks along -z, +x right,
// +y up). The frame is fitted about the box's centre on the plant's axis to
// the projection of the cylinder that holds the box from every azimuth: on
// ring 0, [-halfWidth, halfWidth] along the right axis (u 0 → 1) and
// [bottom, top] in y (image row 0 = top). Depth 0 is the cylinder's front
// along d, 1 its back. Crossed quads need frames divisible by 4 (Double)
// and 6 (Triple): 12 serves all three kinds.

// gpu.impostorQuad of a model from its box: half width = half depth = the
// box's horizontal radius about the plant's axis (x = z = 0), so every frame
// holds the whole plant; bottom and top = the box's y range.
glm::vec4 impostorQuadOf(const gpu::PlantModel& model);

// Shadow frame f of n views the plant the same way from the sun's
// elevation: one ring of frames in an image of its own.

// Both colour images are premultiplied by coverage (the MSAA resolve of a
// clear-0 background): divide rgb and normalDepth by color.a before use.
// Colour layer of (model m, ring r, frame f) = impostor.x + r·frames + f in
// both colour images; shadow layer of (m, f) = impostor.w + f in the shadow
// frames' own, smaller, image; full mip chains.
struct ImpostorAtlas {
    Image color;       // R8G8B8A8_SRGB array, one layer per (model, ring, frame): albedo, alpha = coverage
    Image normalDepth; // R8G8B8A8_UNORM array: plant-space normal·0.5+0.5, alpha = depth across the box (0 front … 1
                       // back)
    Image shadow; // R8G8_UNORM array, shadowFrameSize²: coverage seen from the sun's elevation (shadow frames), depth
                  // along the sun premultiplied by coverage (0 front, toward the sun … 1 back)
    uint32_t mipLevels = 0;
    uint32_t shadowMipLevels = 0;
    VkSampler sampler = VK_NULL_HANDLE; // linear, clamp, mipmapped
    uint32_t layers = 0;                // of the colour images
    uint32_t shadowLayers = 0;          // of the shadow frames' image: one ring per model
    ImpostorSettings settings;
    // Per layer, the rectangle its billboards are drawn as (impostor_outline.h):
    // read back from mip kOutlineMip (or the last, if coarser), grown by
    // kOutlineMargin of its texels, so it holds everything the alpha test
    // keeps at that mip and finer ones and at one mip coarser; smaller
    // billboards may lose a faint fringe.
    std::vector<ImpostorOutline> outlines;
};

constexpr uint32_t kOutlineMip = 3;
constexpr float kOutlineMargin = 2.0f;

// Bakes all models of the pool (already uploaded: vertices as FieldVertex
// storage buffer, indices as index buffer), the colour frames and the shadow
// frames seen from `sunElevation` (radians above the horizon: the scene's
// sun, fixed per scene), writes each model's gpu.impostor (first colour
// layer, frames, quads per billboard from its BillboardKind, first shadow
// layer) and gpu.impostorQuad,
// and leaves the images in SHADER_READ_ONLY_OPTIMAL. The images and the
// sampler are owned by `owner`.
ImpostorAtlas bakeImpostorAtlas(GpuResources& owner, PlantModelPool& pool, const Buffer& vertices,
                                const Buffer& indices, float sunElevation, const ImpostorSettings& settings = {});

// Billboards for the pool's impostor draws: for quads q ∈ {1, 2, 3} the
// vertices and indices the impostor vertex shader expands. Each quad is a
// fan of kOutlineCorners corners (FieldVertex position.x = corner index,
// position.z = quad index) that the shader places at the corners of the
// shown frame's outline. Quad q lies in the plane through the plant's axis
// at azimuth q·180°/quads (quads > 1); a single quad turns to the view, and
// so does quad 0 of crossed ones seen from above the lowest ring (the
// others are dropped). Draw two-sided (no culling). Appends to the pool; returns the mesh range.
MeshRange appendBillboardMesh(PlantModelPool& pool, uint32_t quads);

} // namespace pf
