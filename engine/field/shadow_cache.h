// When the cached map of the sun's static casters serves a frame. The cache
// is a square of the sun's texel grid `margin` texels wider on every side
// than the frame's map, drawn for the camera of the frame that drew it; the
// frames after it copy their window out of it for as long as the camera
// stays within `reach` metres of that camera (so the plants it holds stay
// impostors: shadow_select.h) and their square inside its square, and draw
// it again otherwise.
#pragma once

#include "engine/field/sun_square.h"
#include "engine/scene/camera.h"

#include <cstdint>

namespace pf {

struct ShadowCacheSettings {
    bool reuse = true;            // false: every frame draws the cache again (its map from scratch)
    float reach = 8.0f;           // metres the camera may move from where the cache was drawn
    float pixelTolerance = 0.05f; // fraction the camera's pixels per metre (fov, viewport) may change by
};

// What the casters of a shadow map depend on: the sun and the square of its
// grid, and the camera that decides which plants are drawn at which LOD.
struct ShadowView {
    SunSquare square;
    glm::vec3 sunDirection{0.0f};
    glm::vec3 camera{0.0f};
    float pixelsPerMetre = 0.0f; // the camera's at one metre (makeCullUniforms)
    uint32_t forcedLod = 0xFFFFFFFFu;
};

// The frame's view from the sun: a square of `texels` texels, 2·radius
// metres wide, reaching ahead of `camera` (shadows where they are seen
// large), for a viewport `viewportHeight` pixels high.
ShadowView shadowViewAhead(const Camera& camera, const glm::vec3& sunDirection, float radius, uint32_t texels,
                           uint32_t viewportHeight, uint32_t forcedLod);

// Texels the cache reaches past the frame's map on every side: the camera's
// reach, so a square that moves with it stays inside.
uint32_t shadowCacheMargin(const ShadowCacheSettings& settings, float texel);

// The cache a frame draws when none serves it: its own view, its square
// grown by the margin.
ShadowView shadowCacheFor(const ShadowView& frame, uint32_t margin);

// True when `cache` holds every static caster `frame` needs: the same sun,
// forced LOD and texel grid, the camera within reach and its pixels per metre
// within the tolerance, the frame's square inside the cache's and its depth
// within reach of the cache's (the depth range is the cache's).
bool shadowCacheServes(const ShadowView& cache, const ShadowView& frame, const ShadowCacheSettings& settings);

} // namespace pf
