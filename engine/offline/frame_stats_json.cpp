#include "frame_stats_json.h"

#include "engine/field/field_scopes.h"

#include <nlohmann/json.hpp>

namespace pf {

std::string frameStatsJson(const OfflineRenderer& offline, const std::string& scene) {
    const GpuContext& ctx = offline.context();
    const FieldRenderer& renderer = offline.renderer();
    const FieldFrameStats stats = offline.stats();
    nlohmann::json j;
    j["scene"] = scene;
    j["device"] = ctx.properties.deviceName;
    j["size"] = {offline.size().width, offline.size().height};
    j["time"] = offline.lastTime();
    j["instances"] = stats.instances;
    j["models"] = renderer.content().models.models.size();
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) j["plants_per_lod"][kLodNames[lod]] = stats.plantsPerLod[lod];
    j["visible_entries"] = stats.visibleEntries();
    j["culled"] = stats.culled();
    j["occluded"] = stats.occluded;
    for (uint32_t c = 0; c < DRAW_CLASS_COUNT; ++c) j["draws"][kDrawClassNames[c]] = stats.draws[c];
    j["triangles"] = stats.triangles;
    nlohmann::json& shadow = j["shadow"];
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
        shadow["casters_per_lod"][kLodNames[lod]] = stats.shadowCastersPerLod[lod];
    shadow["cache_casters"] = stats.shadowCacheCasters;
    shadow["cache_renders"] = stats.shadowCacheRenders;
    nlohmann::json& clusters = j["clusters"];
    clusters["far_nodes"] = stats.clustersFar;
    clusters["far_plants"] = stats.clusterFarPlants;
    clusters["near_leaves"] = stats.nearLeaves;
    clusters["near_plants"] = stats.nearPlants;
    j["joints_simulated"] = renderer.simulatedJoints();
    j["indirect_count"] = ctx.drawIndirectCount;
    nlohmann::json ms = nlohmann::json::object();
    double total = 0;
    for (const ScopeTime& s : offline.gpuTimes()) {
        ms[s.name] = s.milliseconds;
        const std::optional<FieldScope> scope = fieldScopeNamed(s.name);
        if (!scope || !fieldScope(*scope).insideColor) total += s.milliseconds;
    }
    ms["total"] = total;
    j["gpu_ms"] = ms;
    j["frame_wall_ms"] = offline.lastWallMs();
    j["gpu_bytes"] = renderer.gpuBytes();
    return j.dump(2);
}

} // namespace pf
