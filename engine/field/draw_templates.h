// The cull pass's draw templates (CullPassInputs::templates, docs/CULLING.md):
// one per (model, LOD, draw class) with geometry and plants, the mesh it
// draws and the visible list its instances come from, sorted by class —
// bark and foliage meshes of LOD0 and LOD1, then every model's impostor
// billboard. Made on the CPU at load. CPU only.
#pragma once

#include "engine/scene/plant_models.h"
#include "shaders/shared/field_layouts.h"

#include <array>
#include <vector>

namespace pf {

// The models' visible lists already assigned (fieldPlantsOf); `billboards`
// the meshes of billboards of 1, 2 and 3 quads (appendBillboardMesh).
std::vector<gpu::DrawTemplate> drawTemplates(const PlantModelPool& pool, const std::array<MeshRange, 3>& billboards);

} // namespace pf
