#pragma once
// Hills and valleys pushed into a height grid: the L-system mountains of the
// clouds-and-mountains chapter (§21–22, docs/TERRAIN_LSYSTEMS.md). Each bump
// is a radial profile about a centre; all bumps are superimposed by adding
// them, so a surface is the sum of every hill and valley on it.

#include <cstdint>
#include <span>
#include <string_view>

#include "lsystem/common/error.h"

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

// Bumps that cannot be made or laid: past a limit (the extreme-peak height,
// the bump budget, kMaxBumpSamples) or with bad parameters.
struct MountainError : DerivationError {
    using DerivationError::DerivationError;
};

// The most bump evaluations addBumps makes (about 10 s of one core): its
// cost is the samples in every bump's bounding square, which a few very
// wide bumps on a fine grid could otherwise make hours.
inline constexpr uint64_t kMaxBumpSamples = uint64_t(1) << 30;

// The samples in the bumps' bounding squares on a grid of `resolution`² over
// `size`: the evaluations addBumps makes.
uint64_t bumpSamples(uint32_t resolution, float size, std::span<const TerrainBump> bumps);

// A square grid of `resolution`² heights, row by row (heights[iz·resolution +
// ix]), its samples spanning [-size/2, size/2] in x and z (as pf::Heightfield
// lays them out): adds every bump, in order, to the samples within its radius.
// The same bumps give the same heights, bit for bit. Throws MountainError
// when bumpSamples is past kMaxBumpSamples, before adding any.
void addBumps(std::span<float> heights, uint32_t resolution, float size, std::span<const TerrainBump> bumps);

} // namespace lsys::landscape
