// The shadows of the clouds that cast one (Cloud::shadow) on the ground:
// the sunlight let through, baked once per scene on the CPU over the plane
// y = 0, where each ground point looks it up by following the sun's ray
// down to that plane (shaders/cloud_shadow.frag). The sun is fixed for a
// scene and the clouds only drift sideways with the wind, so the map moves
// with the wind and is never baked again (docs/CLOUDS.md).
#pragma once

#include "engine/scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace pf {

struct CloudShadowMap {
    glm::vec2 origin{0.0f};           // x, z of texel (0, 0)'s centre on the plane y = 0, metres, at scene time 0
    float texel = 1.0f;               // metres a texel
    uint32_t width = 0, height = 0;   // 0: no cloud casts a shadow (or the sun is too low)
    std::vector<float> transmittance; // width × height, rows along +z: the sunlight let through, 1 at the edges
};

// The most texels a side: past it the texels grow instead.
constexpr uint32_t kCloudShadowMaxSide = 1024;

// The point where the sun's ray through `point` meets the plane y = 0
// (x, z): where the ground at `point` looks its shadow up. `sun` is the
// unit vector toward the sun, above the horizon.
glm::vec2 cloudShadowPlanePoint(const glm::vec3& point, const glm::vec3& sun);

// Texels of `texelMetres` (larger when the clouds' shadows would need more
// than kCloudShadowMaxSide a side) over every casting sphere's shadow and
// two texels more. Each texel holds exp(−1.2 · Σ chord / radius) over the
// spheres its sun ray crosses — the opacity the cloud shader gives one
// sphere, compounded. The sun 3° or less above the horizon casts none.
CloudShadowMap bakeCloudShadows(const std::vector<Cloud>& clouds, const glm::vec3& sun, float texelMetres = 2.0f);

} // namespace pf
