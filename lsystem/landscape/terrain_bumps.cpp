#include "lsystem/landscape/terrain_bumps.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace lsys::landscape {

namespace {

// (1 + cos πt) / 2 for t in [0, 1]: zero slope at both ends.
float cosineFall(float t) { return 0.5f * (1.0f + std::cos(std::numbers::pi_v<float> * t)); }

// Where the mesa's flat top ends, as a fraction of its radius.
constexpr float kMesaTop = 0.5f;

// The samples of a grid inside a bump's bounding square: only they can be
// within its radius. Empty (x0 > x1 or z0 > z1) when none is.
struct SampleSquare {
    uint32_t x0 = 1, x1 = 0, z0 = 1, z1 = 0;
    uint64_t count() const { return x0 > x1 || z0 > z1 ? 0 : uint64_t(x1 - x0 + 1) * (z1 - z0 + 1); }
};

SampleSquare samplesUnder(const TerrainBump& bump, uint32_t resolution, float size) {
    const float spacing = size / float(resolution - 1), last = float(resolution - 1);
    const auto index = [&](float coordinate) { return (coordinate + 0.5f * size) / spacing; };
    const float lowX = index(bump.x - bump.radius), highX = index(bump.x + bump.radius);
    const float lowZ = index(bump.z - bump.radius), highZ = index(bump.z + bump.radius);
    if (!(highX >= 0.0f && highZ >= 0.0f && lowX <= last && lowZ <= last)) return {};
    const auto clamped = [&](float i) { return uint32_t(std::clamp(i, 0.0f, last)); };
    return {clamped(std::ceil(lowX)), clamped(std::floor(highX)), clamped(std::ceil(lowZ)), clamped(std::floor(highZ))};
}

} // namespace

std::string_view bumpShapeName(BumpShape shape) {
    switch (shape) {
    case BumpShape::Hill: return "Hill";
    case BumpShape::Peak: return "Peak";
    case BumpShape::Mesa: return "Mesa";
    case BumpShape::Valley: return "Valley";
    }
    return "?";
}

float bumpProfile(BumpShape shape, float t) {
    if (!(t < 1.0f)) return 0.0f;
    t = std::max(t, 0.0f);
    switch (shape) {
    case BumpShape::Hill:
    case BumpShape::Valley: return cosineFall(t);
    case BumpShape::Peak: return (1.0f - t) * (1.0f - t);
    case BumpShape::Mesa: return t <= kMesaTop ? 1.0f : cosineFall((t - kMesaTop) / (1.0f - kMesaTop));
    }
    return 0.0f;
}

float bumpHeightAt(const TerrainBump& bump, float x, float z) {
    const float distance = std::hypot(x - bump.x, z - bump.z);
    return bump.height * bumpProfile(bump.shape, distance / bump.radius);
}

float bumpsHeightAt(std::span<const TerrainBump> bumps, float x, float z) {
    float sum = 0.0f;
    for (const TerrainBump& bump : bumps) sum += bumpHeightAt(bump, x, z);
    return sum;
}

uint64_t bumpSamples(uint32_t resolution, float size, std::span<const TerrainBump> bumps) {
    if (resolution < 2) return 0;
    uint64_t samples = 0;
    for (const TerrainBump& bump : bumps) samples += samplesUnder(bump, resolution, size).count(); // < 2^26 · 2^32
    return samples;
}

void addBumps(std::span<float> heights, uint32_t resolution, float size, std::span<const TerrainBump> bumps) {
    if (resolution < 2 || heights.size() < size_t(resolution) * resolution) return;
    if (const uint64_t samples = bumpSamples(resolution, size, bumps); samples > kMaxBumpSamples)
        throw MountainError("the terrain's " + std::to_string(bumps.size()) + " bumps cover " +
                            std::to_string(samples) + " height samples between them, more than " +
                            std::to_string(kMaxBumpSamples) +
                            ": give the terrain fewer or narrower bumps, or fewer samples (resolution)");
    const float spacing = size / float(resolution - 1);
    const float start = -0.5f * size;
    for (const TerrainBump& bump : bumps) {
        const SampleSquare square = samplesUnder(bump, resolution, size);
        for (uint32_t iz = square.z0; iz <= square.z1; ++iz)
            for (uint32_t ix = square.x0; ix <= square.x1; ++ix)
                heights[size_t(iz) * resolution + ix] +=
                    bumpHeightAt(bump, start + float(ix) * spacing, start + float(iz) * spacing);
    }
}

} // namespace lsys::landscape
