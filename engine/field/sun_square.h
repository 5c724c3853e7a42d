// The sun's texel grid: squares of the orthographic view along the sun, cut
// into whole texels, that the shadow map and its cache are drawn over
// (shadow_map.h), and their view-projections. CPU only.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace pf {

// Metres the sun's box of a square reaches either side of its depth: its
// view-projections' (sunViewProjection) depth range.
constexpr float kSunDepthRadius = 250.0f;

// A square of the sun's texel grid: the orthographic view along the sun
// whose texels are `texel` metres wide, cut into whole texels, and the depth
// its range is centred on.
struct SunSquare {
    glm::mat4 view{1.0f}; // world → sun view space, looking along −sunDirection
    glm::ivec2 origin{0}; // the square's first texel (lowest x and y) on the grid
    uint32_t texels = 0;  // on a side
    float texel = 0.0f;   // metres
    float depth = 0.0f;   // distance along the view to the plane the depth range is centred on
};

// The square of `texels` texels, 2·radius metres wide, around `focus`. Its
// origin is snapped to whole texels so the shadows of still plants do not
// crawl while the camera moves.
SunSquare sunSquareAround(const glm::vec3& sunDirection, const glm::vec3& focus, float radius, uint32_t texels);
// `square` grown by `margin` texels on every side: the same grid and depth.
SunSquare grownSquare(const SunSquare& square, uint32_t margin);
// True when `inner` lies inside `outer`, both on the same grid.
bool squareContains(const SunSquare& outer, const SunSquare& inner);
// The orthographic view-projection of `square`, `depthRadius` metres deep
// either side of its depth.
glm::mat4 sunViewProjection(const SunSquare& square, float depthRadius);

} // namespace pf
