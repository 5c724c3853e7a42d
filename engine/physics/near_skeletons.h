// Simulation LOD for plants near the camera: up to the scene's
// joint budget, plants close to the camera get a skeleton of their own —
// the wind at their own place, their own scale — instead of following one
// of their model's shared copies. A plant keeps its skeleton (and so its
// motion) while it stays in range; a newcomer starts from the state of the
// shared copy it was following, so nothing jumps. The CPU work per frame
// is over the plants near the camera only (a grid of plants by position).
#pragma once

#include "engine/physics/plant_physics.h"
#include "engine/scene/field_content.h"

#include <glm/glm.hpp>

#include <unordered_map>
#include <vector>

namespace pf {

// Plants bucketed by position on the terrain square (cells in x, z).
struct PlantGrid {
    float cellSize = 16.0f;
    float origin = 0.0f; // world x and z of cell (0, 0)'s corner
    uint32_t cellsPerSide = 0;
    std::vector<uint32_t> cellStart; // cellsPerSide² + 1 offsets into plants
    std::vector<uint32_t> plants;
};

PlantGrid makePlantGrid(const std::vector<PlantInstance>& plants, float terrainSize, float cellSize);
// Plants within `radius` of `centre` (x, z), nearest first (ties by index).
std::vector<uint32_t> plantsNear(const PlantGrid& grid, const std::vector<PlantInstance>& plants,
                                 const glm::vec3& centre, float radius);

// Own skeletons reserved for near plants: per model an equal share of the
// joint budget. Appends them to `set` (after the shared copies) with scale
// 0: free skeletons are not simulated (skeletonInUse).
struct NearSkeletons {
    std::vector<std::vector<uint32_t>> freeOfModel; // own skeletons not in use, per model
    std::unordered_map<uint32_t, uint32_t> ownOf;   // plant → its own skeleton
    float radius = 40.0f;                           // metres from the camera a plant may get one
};

NearSkeletons reserveNearSkeletons(SkeletonSet& set, const PlantModelPool& pool,
                                   const std::vector<PlantInstance>& plants, uint32_t jointBudget);

// The changes of one frame: plants to point at a new skeleton, and own
// skeletons to start from a shared copy's state.
struct NearChanges {
    std::vector<std::pair<uint32_t, uint32_t>> plantSkeleton; // (plant, skeleton it follows now)
    std::vector<std::pair<uint32_t, uint32_t>> startFrom;     // (own skeleton, shared skeleton to copy)
};

// Keeps own skeletons on the plants nearest `camera` that are still in
// range, releases the others, and gives free ones to the nearest newcomers
// (and places them: position, yaw, scale in `skeletons`).
NearChanges updateNearSkeletons(NearSkeletons& near, const PlantGrid& grid, const std::vector<PlantInstance>& plants,
                                const PlantModelPool& pool, const std::vector<uint32_t>& sharedOf,
                                const glm::vec3& camera, gpu::Skeleton* skeletons);
// Every own skeleton back to free (a restart): the plants follow their shared copies again.
NearChanges releaseAllNearSkeletons(NearSkeletons& near, const std::vector<uint32_t>& sharedOf,
                                    gpu::Skeleton* skeletons);

} // namespace pf
