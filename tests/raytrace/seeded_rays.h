#pragma once
// The rays the tracer tests shoot at a plant, the same for the CPU tracers
// and the GPU traversal.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "lsystem/raytrace/ray.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys::test {

// Seeded rays from a sphere around the plant's box towards points in it.
inline std::vector<Ray> raysAt(const Bounds& bounds, size_t count, uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    const float radius = glm::length(bounds.max - bounds.min);
    std::vector<Ray> rays;
    for (size_t i = 0; i < count; ++i) {
        const float z = 2.0f * unit(random) - 1.0f, azimuth = 2.0f * std::numbers::pi_v<float> * unit(random);
        const float ring = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const glm::vec3 origin = centre + radius * glm::vec3(ring * std::cos(azimuth), z, ring * std::sin(azimuth));
        const glm::vec3 target = glm::mix(bounds.min, bounds.max, glm::vec3(unit(random), unit(random), unit(random)));
        rays.push_back({origin, glm::normalize(target - origin)});
    }
    return rays;
}

} // namespace lsys::test
