#include "engine/field/draw_templates.h"

namespace pf {

std::vector<gpu::DrawTemplate> drawTemplates(const PlantModelPool& pool, const std::array<MeshRange, 3>& billboards) {
    std::vector<gpu::DrawTemplate> templates;
    auto add = [&](const MeshRange& mesh, uint32_t drawClass, uint32_t model, uint32_t lod) {
        const glm::uvec4& lists = pool.models[model].gpu.lists;
        if (mesh.indexCount == 0 || lists[PLANT_MODEL_LIST_CAPACITY] == 0) return;
        templates.push_back({glm::uvec4(mesh.indexCount, mesh.firstIndex, mesh.vertexOffset, drawClass),
                             glm::uvec4(model * LOD_COUNT + lod, lists[lod], 0u, 0u)});
    };
    for (uint32_t drawClass : {uint32_t(DRAW_BARK), uint32_t(DRAW_FOLIAGE)})
        for (uint32_t m = 0; m < pool.models.size(); ++m)
            for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
                add(pool.models[m].meshes[lod][drawClass], drawClass, m, lod);
    for (uint32_t m = 0; m < pool.models.size(); ++m)
        add(billboards[pool.models[m].gpu.impostor.z - 1], DRAW_IMPOSTOR, m, LOD_IMPOSTOR);
    return templates;
}

} // namespace pf
