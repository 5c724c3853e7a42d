// What a FieldRenderer's frame drew (FieldFrameStats), from its passes' counters.
#include "engine/field/field_renderer.h"

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

FieldFrameStats FieldRenderer::readStats() const {
    const CullCounts counts = readCullCounts(cull_);
    FieldFrameStats stats;
    stats.instances = uint32_t(content_.plants.size());
    stats.plantsPerLod = counts.perLod;
    stats.draws = counts.drawsPerClass;
    stats.occluded = counts.occluded;
    if (settings_.shadows == SunShadows::shadowMap) {
        stats.shadowCastersPerLod = readCullCounts(shadowFrameCasters_).perLod;
        stats.shadowCacheCasters = readCullCounts(shadowCacheCasters_).perLod[LOD_IMPOSTOR];
        stats.shadowCacheRenders = shadowCacheRenders_;
    }
    if (settings_.clusters.enabled) {
        const std::array<uint32_t, CLUSTER_STAT_COUNT> cut = readClusterStats(clusters_);
        stats.clustersFar = cut[CLUSTER_STAT_FAR];
        stats.clusterFarPlants = cut[CLUSTER_STAT_FAR_PLANTS];
        stats.nearLeaves = cut[CLUSTER_STAT_NEAR_LEAVES];
        stats.nearPlants = cut[CLUSTER_STAT_NEAR_PLANTS];
        stats.triangles += uint64_t(stats.clustersFar) * (clusters_.farMesh.indexCount / 3);
    }
    const PlantModelPool& pool = content_.models;
    for (size_t m = 0; m < pool.models.size(); ++m) {
        const PlantModelInfo& model = pool.models[m];
        for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
            stats.triangles += uint64_t(counts.perModelLod[m * LOD_COUNT + lod]) * model.triangles(lod);
        stats.triangles +=
            uint64_t(counts.perModelLod[m * LOD_COUNT + LOD_IMPOSTOR]) * (kOutlineCorners - 2) * model.gpu.impostor.z;
    }
    return stats;
}

uint64_t FieldRenderer::naiveTriangles() const {
    uint64_t triangles = 0;
    const PlantModelPool& pool = content_.models;
    for (const PlantInstance& p : content_.plants)
        triangles += pool.models[pool.modelOf(p.species, p.variant)].triangles(LOD_FULL);
    return triangles;
}

} // namespace pf
