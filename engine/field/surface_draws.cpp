#include "engine/field/surface_draws.h"

#include "engine/field/draw_sets.h"
#include "engine/field/field_scopes.h"

#include <span>

namespace pf {
namespace {

// One draw per plant and class, its full-detail mesh; firstInstance picks
// the plant's entry of the naive list.
void drawPlantsNaive(VkCommandBuffer cmd, const FieldContent& content, bool bark, bool foliage) {
    const PlantModelPool& pool = content.models;
    for (uint32_t i = 0; i < content.plants.size(); ++i) {
        const PlantInstance& p = content.plants[i];
        const PlantModelInfo& model = pool.models[pool.modelOf(p.species, p.variant)];
        for (uint32_t drawClass = 0; drawClass < kMeshClassCount; ++drawClass) {
            if ((drawClass == DRAW_BARK && !bark) || (drawClass == DRAW_FOLIAGE && !foliage)) continue;
            const MeshRange& mesh = model.meshes[LOD_FULL][drawClass];
            if (mesh.indexCount > 0)
                vkCmdDrawIndexed(cmd, mesh.indexCount, 1, mesh.firstIndex, int32_t(mesh.vertexOffset), i);
        }
    }
}

void drawPlantMeshes(VkCommandBuffer cmd, const SurfaceGeometry& geometry, const SurfaceLists& lists, bool bark,
                     bool foliage) {
    if (!lists.plants) {
        drawPlantsNaive(cmd, *geometry.content, bark, foliage);
        return;
    }
    if (bark) drawClassIndirect(cmd, *geometry.ctx, *lists.plants, DRAW_BARK, lists.phase);
    if (foliage) drawClassIndirect(cmd, *geometry.ctx, *lists.plants, DRAW_FOLIAGE, lists.phase);
}

void drawTerrainRanges(VkCommandBuffer cmd, std::span<const IndexRange> ranges) {
    for (const IndexRange& range : ranges) vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
}

} // namespace

void recordSurfaceDraws(VkCommandBuffer cmd, const SurfaceGeometry& geometry, const SurfacePipelines& pipelines,
                        const SurfaceLists& lists, GpuTimer* timer) {
    {
        TimedFieldScope scope(cmd, timer, FieldScope::plants, ScopeStart::insideRendering);
        vkCmdBindIndexBuffer(cmd, geometry.indices->buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.bark);
        if (pipelines.foliage == pipelines.bark) {
            drawPlantMeshes(cmd, geometry, lists, true, true);
        } else {
            drawPlantMeshes(cmd, geometry, lists, true, false);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.foliage);
            drawPlantMeshes(cmd, geometry, lists, false, true);
        }
    }
    {
        // The colour pass draws the list twice: those the shadow map may
        // reach, then the rest with no shadow lookup (shaders/shared/sunlit_select.h);
        // each draw drops the other's impostors in its vertex shader.
        TimedFieldScope scope(cmd, timer, FieldScope::impostors, ScopeStart::insideRendering);
        for (const ImpostorDraw& draw : pipelines.impostors) {
            if (!lists.plants || draw.pipeline == VK_NULL_HANDLE) continue;
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline);
            if (draw.part != IMPOSTOR_PART_NONE) pushFieldPass(cmd, geometry.layout, pipelines.pass, draw.part);
            drawClassIndirect(cmd, *geometry.ctx, *lists.plants, DRAW_IMPOSTOR, lists.phase);
        }
    }
    {
        TimedFieldScope scope(cmd, timer, FieldScope::canopy, ScopeStart::insideRendering);
        if (lists.far && pipelines.canopy != VK_NULL_HANDLE) {
            // One instance per far node; the cluster pass wrote the count.
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.canopy);
            vkCmdBindIndexBuffer(cmd, geometry.canopyIndices->buffer, 0, VK_INDEX_TYPE_UINT32);
            drawCanopyIndirect(cmd, *geometry.ctx, *lists.far);
        }
    }
    TimedFieldScope scope(cmd, timer, FieldScope::terrainSky, ScopeStart::insideRendering);
    // Last, behind everything: only pixels no plant covers are shaded (the
    // depth test runs before these shaders, which never discard). With
    // occlusion culling the terrain is the early phase's main occluder; the
    // sky, drawn with it, writes no depth and is covered by what the late
    // phase draws.
    if (!lists.terrain) return;
    if (pipelines.terrain != VK_NULL_HANDLE) {
        vkCmdBindIndexBuffer(cmd, geometry.terrainIndices->buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.terrain);
        drawTerrainRanges(cmd, lists.terrain->shadowed);
        if (pipelines.sunlitTerrain != VK_NULL_HANDLE) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sunlitTerrain);
            drawTerrainRanges(cmd, lists.terrain->sunlit);
        }
    }
    if (pipelines.sky != VK_NULL_HANDLE) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sky);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
}

} // namespace pf
