#include "lsystem/landscape/terrain_bumps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lsys::landscape {

namespace {

// (1 + cos πt) / 2 for t in [0, 1]: zero slope at both ends.
float cosineFall(float t) { return 0.5f * (1.0f + std::cos(std::numbers::pi_v<float> * t)); }

// Where the mesa's flat top ends, as a fraction of its radius.
constexpr float kMesaTop = 0.5f;

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

void addBumps(std::span<float> heights, uint32_t resolution, float size, std::span<const TerrainBump> bumps) {
    if (resolution < 2 || heights.size() < size_t(resolution) * resolution) return;
    const float spacing = size / float(resolution - 1);
    const float start = -0.5f * size;
    const auto column = [&](float coordinate) { return (coordinate - start) / spacing; };
    const auto clampIndex = [&](float index) { return uint32_t(std::clamp(index, 0.0f, float(resolution - 1))); };
    for (const TerrainBump& bump : bumps) {
        // Only the samples in the bump's bounding square can be within its radius.
        const float lowX = column(bump.x - bump.radius), highX = column(bump.x + bump.radius);
        const float lowZ = column(bump.z - bump.radius), highZ = column(bump.z + bump.radius);
        if (highX < 0.0f || highZ < 0.0f || lowX > float(resolution - 1) || lowZ > float(resolution - 1)) continue;
        const uint32_t x0 = clampIndex(std::ceil(lowX)), x1 = clampIndex(std::floor(highX));
        const uint32_t z0 = clampIndex(std::ceil(lowZ)), z1 = clampIndex(std::floor(highZ));
        for (uint32_t iz = z0; iz <= z1; ++iz)
            for (uint32_t ix = x0; ix <= x1; ++ix)
                heights[size_t(iz) * resolution + ix] +=
                    bumpHeightAt(bump, start + float(ix) * spacing, start + float(iz) * spacing);
    }
}

} // namespace lsys::landscape
