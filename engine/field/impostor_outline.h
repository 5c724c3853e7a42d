// The outline of one impostor frame: the rectangle, in the frame's texture
// space, around every texel the billboard's alpha test can keep. Billboards
// are drawn as this rectangle instead of the whole frame (which is as wide
// as the plant's widest view and as tall as its box), so the rasteriser
// never generates the fragments of the frame's empty margins: on lavapipe
// each of those costs an atlas fetch before its discard. A tighter polygon
// was measured and lost: on a CPU rasteriser every extra triangle costs more
// than the fragments it saves (docs/IMPOSTORS.md).
#pragma once

#include "shaders/shared/field_layouts.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace pf {

constexpr uint32_t kOutlineCorners = OUTLINE_CORNERS;
static_assert(kOutlineCorners == 4, "the outline is a rectangle, corner order below");

// Corners (u0, v0), (u1, v0), (u1, v1), (u0, v1): uv in [0, 1]² with v = 0 at
// the top (the atlas's texture space). An empty frame has all corners at one
// point (nothing is drawn).
using ImpostorOutline = std::array<glm::vec2, kOutlineCorners>;
static_assert(sizeof(ImpostorOutline) == IMPOSTOR_OUTLINE_TEXELS * 16, "uploaded as is, read as texels");

// `alpha`: size × size coverage values of one frame at some mip level, row 0
// at the top. Every texel with non-zero alpha, grown by `marginTexels` on
// every side (bilinear filtering reaches half a texel further, coarser mips
// further still) and clipped to the frame, lies inside the outline.
ImpostorOutline impostorOutline(std::span<const uint8_t> alpha, uint32_t size, float marginTexels);

// The outline's area in uv units (the share of the frame it covers).
float outlineArea(const ImpostorOutline& outline);

} // namespace pf
