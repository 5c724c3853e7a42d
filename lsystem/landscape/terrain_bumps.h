#pragma once
// Hills and valleys pushed into a height grid: the L-system mountains of the
// clouds-and-mountains chapter (§21–22, docs/TERRAIN_LSYSTEMS.md). Each bump
// is a radial profile about a centre; all bumps are superimposed by adding
// them, so a surface is the sum of every hill and valley on it.

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>

namespace lsys::landscape {

// The silhouette of a bump, of t = distance / radius in [0, 1]; every one is 1
// at its centre (t = 0) and 0 from its rim (t ≥ 1) outwards.
enum class BumpShape : uint8_t {
    Hill,   // (1 + cos πt) / 2: a smooth round hill, level at its top and its foot
    Peak,   // (1 − t)²: a pointed summit with concave flanks
    Mesa,   // 1 inside t ≤ ½, then a smooth (cosine) fall to the rim: a flat-topped plateau
    Valley, // the hill's profile; the bump's height is negated where it is made
};

// The module name of a shape ("Hill", "Peak", "Mesa", "Valley").
std::string_view bumpShapeName(BumpShape shape);

struct TerrainBump {
    float x = 0.0f, z = 0.0f; // centre, metres
    float height = 0.0f;      // metres at the centre; negative digs (a valley, or a hill below the start)
    float radius = 0.0f;      // metres, > 0
    BumpShape shape = BumpShape::Hill;
    bool operator==(const TerrainBump&) const = default;
};

// The shape's profile at t = distance / radius: 1 at t = 0, 0 for t ≥ 1.
float bumpProfile(BumpShape shape, float t);

// The bump's height at (x, z): height · profile(distance / radius).
float bumpHeightAt(const TerrainBump& bump, float x, float z);

// The sum of every bump's height at (x, z), added in the bumps' order.
float bumpsHeightAt(std::span<const TerrainBump> bumps, float x, float z);

// A square grid of `resolution`² heights, row by row (heights[iz·resolution +
// ix]), its samples spanning [-size/2, size/2] in x and z (as pf::Heightfield
// lays them out): adds every bump, in order, to the samples within its radius.
// The same bumps give the same heights, bit for bit.
void addBumps(std::span<float> heights, uint32_t resolution, float size, std::span<const TerrainBump> bumps);

} // namespace lsys::landscape
