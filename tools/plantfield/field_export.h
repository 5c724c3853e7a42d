// A whole field as glTF 2.0 (`plantfield --export FIELD.glb|.gltf`) and its
// plants as a placements table (`--export-placements FILE.csv|.json`), built
// from the CPU side of the field alone (engine/scene/field_content.h): no
// Vulkan device. docs/EXPORT.md "Whole fields" describes the files.
#pragma once

#include "engine/scene/field_content.h"
#include "lsystem/common/memory_budget.h"

#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <filesystem>

namespace pf {

struct FieldExportOptions {
    // true: one node per plant model carrying EXT_mesh_gpu_instancing
    // (TRANSLATION, ROTATION, SCALE of every plant of the model); false: one
    // plain node per plant, for loaders that ignore the extension.
    bool gpuInstancing = true;
    // What the writer holds at once (the meshes, their copies in the glTF
    // buffer and its encoding, about 2 kB a node) must fit, checked before
    // any mesh is built: lsys::MemoryBudgetError (stage "export") past it.
    lsys::MemoryBudget memory = lsys::machineMemoryBudget();
};

struct FieldExportSummary {
    size_t meshes = 0; // plant models with triangles, plus the terrain
    size_t nodes = 0;
    size_t plants = 0;
    size_t materials = 0;
};

// Writes the field: the terrain as one mesh, one mesh per plant model (its
// LOD0 geometry baked again from the model's plant, scaled as the model: the
// renderer's up-close bark and blades, bit for bit, with leaf cards as the
// leaf outlines `lsys export` writes; one primitive per material), materials (one per distinct albedo and surface kind,
// metallic 0, roughness 1, leaves and blades double-sided) and the plants, as `options` says. The extension (.glb or
// .gltf, any case) chooses the format. Written to a temporary file and renamed into place
// (lsystem/common/output_file.h), so a failure leaves no file and never replaces one. Throws std::runtime_error
// starting "export PATH:", also when `content` was built without its models'
// plants (buildFieldContent with ModelAssets::Keep).
FieldExportSummary exportField(const FieldContent& content, const std::filesystem::path& path,
                               const FieldExportOptions& options = {});

// Writes every plant, in the field's order: species, model, x, y, z, qx, qy,
// qz, qw, scale. .csv: that header line, then one line a plant; .json: an
// array of objects with those keys. Floats written with the fewest digits
// that read back to the same float. Written whole or not at all, as above.
void exportPlacements(const FieldContent& content, const std::filesystem::path& path);

// The rotation of a plant standing at `yaw` radians about +y, as the renderer
// turns it (shaders/field_common.glsl yawMatrix).
glm::quat yawRotation(float yaw);

} // namespace pf
