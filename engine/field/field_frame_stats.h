// What a frame of the field drew (FieldFrameStats, filled by
// FieldRenderer::readStats from its passes' counters), the names the tools
// print its counts under, and the triangles its draws and the naive
// baseline's add up to. CPU only.
#pragma once

#include "engine/scene/field_content.h"
#include "shaders/shared/field_layouts.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace pf {

// Names of the LODs and draw classes in statistics, reports and the overlay.
inline constexpr std::array<const char*, LOD_COUNT> kLodNames = {"full", "reduced", "impostor"};
inline constexpr std::array<const char*, DRAW_CLASS_COUNT> kDrawClassNames = {"bark", "foliage", "impostor"};

// What the last recorded frame drew, from the cull pass's counters.
struct FieldFrameStats {
    uint32_t instances = 0;
    std::array<uint32_t, LOD_COUNT> plantsPerLod{}; // fading plants count at both LODs
    std::array<uint32_t, DRAW_CLASS_COUNT> draws{}; // indirect commands per class
    uint64_t triangles = 0;                         // colour pass, plants and canopy
    uint32_t occluded =
        0; // in view and large enough to draw, hidden by the depth pyramid (0 without occlusion culling)
    // The sun's shadow map (zero without it): plants drawn into this
    // frame's map on top of the cache, per LOD; impostors the cache holds
    // (as last drawn); times this renderer has drawn the cache.
    std::array<uint32_t, LOD_COUNT> shadowCastersPerLod{};
    uint32_t shadowCacheCasters = 0;
    uint64_t shadowCacheRenders = 0;
    // The cut through the clusters (zero without clusters): nodes drawn as
    // canopy and their plants, leaves whose plants the per-plant cull ran
    // over and their plants; plants in neither were culled with their leaf.
    uint32_t clustersFar = 0, clusterFarPlants = 0;
    uint32_t nearLeaves = 0, nearPlants = 0;

    // Entries of every visible list: a fading plant counts twice.
    uint32_t visibleEntries() const;
    // Plants in no list and in no far node: not in view, too small to draw, or occluded.
    uint32_t culled() const;
};

// "full 3  reduced 40  impostor 900": plants per LOD, for logs and the overlay.
std::string plantsPerLodText(const FieldFrameStats& stats);

// Triangles of the plant draws of visible lists holding `perModelLod` entries
// ([model · LOD_COUNT + lod], CullCounts::perModelLod): meshes at their
// LOD, impostors as their billboards' outlines.
uint64_t plantTriangles(const PlantModelPool& pool, std::span<const uint32_t> perModelLod);

// What the naive baseline's colour pass draws: every plant's full-detail meshes.
uint64_t naiveTriangles(const FieldContent& content);

} // namespace pf
