// Terrains with known shapes and independent geometric checks for the terrain and placement tests.
#pragma once

#include "engine/scene/placement.h"
#include "engine/scene/terrain.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

namespace fieldtest {

// heights = f(x, z) sampled on a resolution² grid of side `size`.
inline pf::Heightfield sampledTerrain(uint32_t resolution, float size, const std::function<float(float, float)>& f) {
    pf::Heightfield terrain{resolution, size, std::vector<float>(size_t(resolution) * resolution)};
    for (uint32_t iz = 0; iz < resolution; ++iz)
        for (uint32_t ix = 0; ix < resolution; ++ix)
            terrain.heights[size_t(iz) * resolution + ix] = f(terrain.coordinate(ix), terrain.coordinate(iz));
    return terrain;
}

inline pf::Heightfield flatTerrain(float size) {
    return sampledTerrain(2, size, [](float, float) { return 0.0f; });
}

inline glm::vec2 ground(const pf::PlantInstance& instance) { return {instance.position.x, instance.position.z}; }

inline std::vector<glm::vec2> groundPoints(const std::vector<pf::PlantInstance>& instances) {
    std::vector<glm::vec2> points;
    for (const pf::PlantInstance& instance : instances) points.push_back(ground(instance));
    return points;
}

// Nearest-point queries by a bucket grid of its own, independent of the
// placement's grid.
class NearestPoints {
public:
    NearestPoints(const std::vector<glm::vec2>& points, float size, float cell)
        : points_(points), origin_(-0.5f * size), cell_(cell), side_(int(size / cell) + 1),
          buckets_(size_t(side_) * side_) {
        for (size_t i = 0; i < points.size(); ++i)
            buckets_[bucket(cellOf(points[i].x), cellOf(points[i].y))].push_back(i);
    }

    // Distance from p to the nearest point other than `exclude`, searched out
    // to `within` (infinity when none is that close).
    float nearest(glm::vec2 p, float within, size_t exclude = size_t(-1)) const {
        const int reach = int(within / cell_) + 1;
        float best = std::numeric_limits<float>::infinity();
        for (int z = std::max(cellOf(p.y) - reach, 0); z <= std::min(cellOf(p.y) + reach, side_ - 1); ++z)
            for (int x = std::max(cellOf(p.x) - reach, 0); x <= std::min(cellOf(p.x) + reach, side_ - 1); ++x)
                for (size_t i : buckets_[bucket(x, z)])
                    if (i != exclude) best = std::min(best, glm::distance(points_[i], p));
        return best <= within ? best : std::numeric_limits<float>::infinity();
    }

    // Smallest distance between two of the points.
    float minimumPairDistance(float within) const {
        float best = std::numeric_limits<float>::infinity();
        for (size_t i = 0; i < points_.size(); ++i) best = std::min(best, nearest(points_[i], within, i));
        return best;
    }

private:
    int cellOf(float v) const { return std::clamp(int((v - origin_) / cell_), 0, side_ - 1); }
    size_t bucket(int x, int z) const { return size_t(z) * size_t(side_) + size_t(x); }

    std::vector<glm::vec2> points_;
    float origin_, cell_;
    int side_;
    std::vector<std::vector<size_t>> buckets_;
};

// Largest distance from a probe point (a lattice `step` apart, over the
// square shrunk by `margin`, where probeHere holds) to its nearest plant: the
// radius of the largest empty disk, to within `step`. Holes wider than
// `searchRadius` come back as infinity.
inline float largestEmptyRadius(
    const std::vector<glm::vec2>& points, float size, float margin, float step, float searchRadius,
    const std::function<bool(glm::vec2)>& probeHere = [](glm::vec2) { return true; }) {
    const NearestPoints nearest(points, size, searchRadius);
    float largest = 0;
    for (float z = -0.5f * size + margin; z <= 0.5f * size - margin; z += step)
        for (float x = -0.5f * size + margin; x <= 0.5f * size - margin; x += step)
            if (probeHere({x, z})) largest = std::max(largest, nearest.nearest({x, z}, searchRadius));
    return largest;
}

} // namespace fieldtest
