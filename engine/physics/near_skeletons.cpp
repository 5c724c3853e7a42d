#include "engine/physics/near_skeletons.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace pf {
namespace {

uint32_t cellOf(const PlantGrid& grid, float x) {
    const float c = std::floor((x - grid.origin) / grid.cellSize);
    return uint32_t(std::clamp(c, 0.0f, float(grid.cellsPerSide - 1)));
}

} // namespace

PlantGrid makePlantGrid(const std::vector<PlantInstance>& plants, float terrainSize, float cellSize) {
    PlantGrid grid;
    grid.cellSize = cellSize;
    grid.origin = -0.5f * terrainSize;
    grid.cellsPerSide = std::max(1u, uint32_t(std::ceil(terrainSize / cellSize)));
    const size_t cells = size_t(grid.cellsPerSide) * grid.cellsPerSide;
    std::vector<uint32_t> cellOfPlant(plants.size());
    grid.cellStart.assign(cells + 1, 0);
    for (size_t i = 0; i < plants.size(); ++i) {
        cellOfPlant[i] = cellOf(grid, plants[i].position.z) * grid.cellsPerSide + cellOf(grid, plants[i].position.x);
        ++grid.cellStart[cellOfPlant[i] + 1];
    }
    for (size_t c = 0; c < cells; ++c) grid.cellStart[c + 1] += grid.cellStart[c];
    grid.plants.resize(plants.size());
    std::vector<uint32_t> next(grid.cellStart.begin(), grid.cellStart.end() - 1);
    for (uint32_t i = 0; i < plants.size(); ++i) grid.plants[next[cellOfPlant[i]]++] = i;
    return grid;
}

std::vector<uint32_t> plantsNear(const PlantGrid& grid, const std::vector<PlantInstance>& plants,
                                 const glm::vec3& centre, float radius) {
    std::vector<std::pair<float, uint32_t>> found;
    const uint32_t x0 = cellOf(grid, centre.x - radius), x1 = cellOf(grid, centre.x + radius);
    const uint32_t z0 = cellOf(grid, centre.z - radius), z1 = cellOf(grid, centre.z + radius);
    for (uint32_t z = z0; z <= z1; ++z)
        for (uint32_t x = x0; x <= x1; ++x) {
            const uint32_t cell = z * grid.cellsPerSide + x;
            for (uint32_t k = grid.cellStart[cell]; k < grid.cellStart[cell + 1]; ++k) {
                const uint32_t i = grid.plants[k];
                const float d =
                    glm::distance(glm::vec2(plants[i].position.x, plants[i].position.z), glm::vec2(centre.x, centre.z));
                if (d <= radius) found.push_back({d, i});
            }
        }
    std::sort(found.begin(), found.end());
    std::vector<uint32_t> nearest(found.size());
    for (size_t k = 0; k < found.size(); ++k) nearest[k] = found[k].second;
    return nearest;
}

NearSkeletons reserveNearSkeletons(SkeletonSet& set, const PlantModelPool& pool,
                                   const std::vector<PlantInstance>& plants, uint32_t jointBudget) {
    std::vector<uint32_t> plantsOfModel(pool.models.size(), 0);
    for (const PlantInstance& p : plants) ++plantsOfModel[pool.modelOf(p.species, p.variant)];
    NearSkeletons near;
    near.freeOfModel.resize(pool.models.size());
    const uint32_t share = pool.models.empty() ? 0 : jointBudget / uint32_t(pool.models.size());
    for (uint32_t m = 0; m < pool.models.size(); ++m) {
        const PlantModelInfo& model = pool.models[m];
        const uint32_t count = std::min(plantsOfModel[m], model.joints > 0 ? share / model.joints : 0u);
        // Reserved in reverse so the lowest index is handed out first.
        for (uint32_t k = 0; k < count; ++k)
            near.freeOfModel[m].push_back(
                addSkeleton(set, m, model.firstJoint, model.joints, glm::vec3(0.0f), 0.0f, 0.0f));
        std::reverse(near.freeOfModel[m].begin(), near.freeOfModel[m].end());
    }
    return near;
}

NearChanges updateNearSkeletons(NearSkeletons& near, const PlantGrid& grid, const std::vector<PlantInstance>& plants,
                                const PlantModelPool& pool, const std::vector<uint32_t>& sharedOf,
                                const glm::vec3& camera, gpu::Skeleton* skeletons) {
    const std::vector<uint32_t> inRange = plantsNear(grid, plants, camera, near.radius);
    const std::unordered_set<uint32_t> keep(inRange.begin(), inRange.end());
    NearChanges changes;
    // Out of range: back to the shared copy, the skeleton to the free list.
    std::vector<uint32_t> leaving;
    for (const auto& [plant, own] : near.ownOf)
        if (!keep.count(plant)) leaving.push_back(plant);
    std::sort(leaving.begin(), leaving.end()); // the map's order is not deterministic
    for (uint32_t plant : leaving) {
        const PlantInstance& p = plants[plant];
        near.freeOfModel[pool.modelOf(p.species, p.variant)].push_back(near.ownOf[plant]);
        skeletons[near.ownOf[plant]].scale.x = 0.0f; // not simulated while free
        near.ownOf.erase(plant);
        changes.plantSkeleton.push_back({plant, sharedOf[plant]});
    }
    // Newcomers, nearest first, while their model has a free skeleton.
    for (uint32_t plant : inRange) {
        if (near.ownOf.count(plant)) continue;
        const PlantInstance& p = plants[plant];
        std::vector<uint32_t>& free = near.freeOfModel[pool.modelOf(p.species, p.variant)];
        if (free.empty()) continue;
        const uint32_t own = free.back();
        free.pop_back();
        near.ownOf[plant] = own;
        skeletons[own].placement = gpu::vec4(p.position, p.rotation);
        skeletons[own].scale = gpu::vec4(p.scale, 0.0f, 0.0f, 0.0f);
        changes.plantSkeleton.push_back({plant, own});
        changes.startFrom.push_back({own, sharedOf[plant]});
    }
    return changes;
}

NearChanges releaseAllNearSkeletons(NearSkeletons& near, const std::vector<uint32_t>& sharedOf,
                                    gpu::Skeleton* skeletons) {
    NearChanges changes;
    std::vector<std::pair<uint32_t, uint32_t>> owned(near.ownOf.begin(), near.ownOf.end());
    std::sort(owned.begin(), owned.end());
    for (const auto& [plant, own] : owned) {
        changes.plantSkeleton.push_back({plant, sharedOf[plant]});
        near.freeOfModel[skeletons[own].ids.x].push_back(own);
        skeletons[own].scale.x = 0.0f;
    }
    near.ownOf.clear();
    // Lowest index handed out first again, as after reserveNearSkeletons:
    // a restart assigns exactly as a fresh start does.
    for (std::vector<uint32_t>& free : near.freeOfModel) std::sort(free.rbegin(), free.rend());
    return changes;
}

} // namespace pf
