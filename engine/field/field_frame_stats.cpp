#include "engine/field/field_frame_stats.h"

#include "engine/field/impostor_outline.h"

namespace pf {

uint32_t FieldFrameStats::visibleEntries() const {
    uint32_t entries = 0;
    for (uint32_t plants : plantsPerLod) entries += plants;
    return entries;
}

uint32_t FieldFrameStats::culled() const {
    const uint32_t shown = visibleEntries() + clusterFarPlants;
    return instances > shown ? instances - shown : 0;
}

std::string plantsPerLodText(const FieldFrameStats& stats) {
    std::string text;
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
        text += (lod ? "  " : "") + std::string(kLodNames[lod]) + " " + std::to_string(stats.plantsPerLod[lod]);
    return text;
}

uint64_t plantTriangles(const PlantModelPool& pool, std::span<const uint32_t> perModelLod) {
    uint64_t triangles = 0;
    for (size_t m = 0; m < pool.models.size(); ++m) {
        const PlantModelInfo& model = pool.models[m];
        for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
            triangles += uint64_t(perModelLod[m * LOD_COUNT + lod]) * model.triangles(lod);
        triangles += uint64_t(perModelLod[m * LOD_COUNT + LOD_IMPOSTOR]) * (kOutlineCorners - 2) * model.gpu.impostor.z;
    }
    return triangles;
}

uint64_t naiveTriangles(const FieldContent& content) {
    uint64_t triangles = 0;
    const PlantModelPool& pool = content.models;
    for (const PlantInstance& p : content.plants)
        triangles += pool.models[pool.modelOf(p.species, p.variant)].triangles(LOD_FULL);
    return triangles;
}

} // namespace pf
