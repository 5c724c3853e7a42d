// The meshes the field draws: every species variant of a scene derived from
// its L-system and interpreted by the turtle, or generated from its model
// file (a ramification tree or a component plant), scaled to the species height and
// baked into triangle meshes at two levels of detail, all in one vertex and
// one index pool (shaders/shared/field_layouts.h FieldVertex). CPU only.
#pragma once

#include "engine/scene/scene.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/turtle/plant_asset.h"
#include "shaders/shared/field_layouts.h"
#include "shaders/shared/physics_layouts.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pf {

// A range of the index pool: indices are relative to vertexOffset.
struct MeshRange {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0; // 0: nothing of this class at this LOD
    uint32_t vertexOffset = 0;
    bool operator==(const MeshRange&) const = default;
};

// Mesh LODs that have geometry: those before LOD_IMPOSTOR (the impostor is baked later).
inline constexpr uint32_t kMeshLodCount = LOD_IMPOSTOR;
// Draw classes that have geometry: DRAW_BARK and DRAW_FOLIAGE.
inline constexpr uint32_t kMeshClassCount = 2;

struct PlantModelInfo {
    uint32_t species = 0;                                                     // index into Scene::species
    uint32_t variant = 0;                                                     // 0 .. variants-1
    std::string name;                                                         // "<species name>#<variant>"
    std::array<std::array<MeshRange, kMeshClassCount>, kMeshLodCount> meshes; // [lod][class]
    uint32_t joints = 0;                                                      // joints of the skeleton (segments)
    uint32_t firstJoint = 0; // its JointParams in PlantModelPool::joints (vertices' joint.x index from here)
    // sphere, boxMin, boxMax and lod filled from the mesh and the species'
    // LodHints (lod.z hysteresis 0.1, lod.w fade 0.25 s); lists and impostor
    // are left for the renderer and the impostor baker.
    gpu::PlantModel gpu{};
    BillboardKind billboard = BillboardKind::Double;

    uint32_t triangles(uint32_t lod) const { return (meshes[lod][0].indexCount + meshes[lod][1].indexCount) / 3; }
};

// A model's plant before it was baked: what the whole-field export bakes
// again with its own options (tools/plantfield/field_export.h).
struct PlantModelAsset {
    lsys::PlantAsset asset; // the species' material overrides applied
    float scale = 1.0f;     // what scaled the model's meshes to the species height
};

// Whether building the pool keeps each model's PlantModelAsset: the renderer
// needs only the meshes, so it does not hold the plants too.
enum class ModelAssets : uint8_t { Drop, Keep };

struct PlantModelPool {
    std::vector<gpu::FieldVertex> vertices;
    std::vector<uint32_t> indices;
    // Every model's skeleton (buildJointParams at the model's height scale), model after model.
    std::vector<gpu::JointParams> joints;
    std::vector<PlantModelInfo> models;  // species by species, variants in order
    std::vector<uint32_t> firstModel;    // per species: index of its variant 0 in models
    std::vector<PlantModelAsset> assets; // per model with ModelAssets::Keep, else empty
    // The species' L-system warnings (a `//` that cuts a cpfg production, a
    // view-file label plantfield ignores …), each line naming the species and
    // file:line:column; empty when there are none. The tools print them.
    std::string warnings;
    uint32_t modelOf(uint32_t species, uint32_t variant) const { return firstModel[species] + variant; }
};

// Called after each model with (models done, models in all, model name).
using ModelProgress = std::function<void(size_t, size_t, const std::string&)>;

// Derives and bakes every variant of every species, each derivation and
// turtle within `memory`, keeping the plants as `assets` says. Same scene ⇒
// same pool, bit for bit. Throws SceneError naming the species and its
// L-system or model file (with line and column) when a file does not parse
// or derive, and lsys::MemoryBudgetError / lsys::ModuleBudgetError naming
// the species when it grows past a budget.
PlantModelPool buildPlantModels(const Scene& scene, const ModelProgress& progress = {},
                                const lsys::MemoryBudget& memory = lsys::machineMemoryBudget(),
                                ModelAssets assets = ModelAssets::Drop);

} // namespace pf
