// The drawn terrain mesh in square chunks of cells, so a frame draws only the
// chunks its view can see. On a CPU rasteriser (lavapipe) every triangle of a
// draw is shaded at its vertices and clipped on one thread before any pixel
// is filled; a view sees a third of the terrain or less.
#pragma once

#include "engine/scene/terrain.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace pf {

struct TerrainChunk {
    uint32_t firstIndex = 0; // into TerrainChunks::indices
    uint32_t indexCount = 0;
    glm::vec3 boxMin{0.0f}, boxMax{0.0f}; // of its vertices
};

// The mesh's triangles reordered chunk by chunk: chunk (cx, cz) holds the
// cells of columns [cx·cells, (cx+1)·cells) and rows [cz·cells, (cz+1)·cells),
// fewer at the far edges, each cell's two triangles as makeTerrainMesh
// writes them; chunks in rows of increasing z.
struct TerrainChunks {
    std::vector<uint32_t> indices;
    std::vector<TerrainChunk> chunks;
};

// `cellsPerChunk` at least 1. Throws on a mesh whose vertices are not a
// square grid (resolution² of them).
TerrainChunks makeTerrainChunks(const TerrainMesh& mesh, uint32_t resolution, uint32_t cellsPerChunk);

// A run of TerrainChunks::indices to draw.
struct IndexRange {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    bool operator==(const IndexRange&) const = default;
};

// What a view draws of the chunks, as ranges of TerrainChunks::indices:
// those the sun's shadow map may reach, drawn with its lookup, and the rest.
struct TerrainRanges {
    std::vector<IndexRange> shadowed;
    std::vector<IndexRange> sunlit;
};

// The chunks whose boxes may be seen through `viewProj` (clip space with
// Vulkan's depth 0…1; a box is left out only when all its corners are beyond
// one clip plane), nearest to `eye` first so the depth test keeps nearer
// hills from shading what they hide. A chunk is sunlit when there is no
// `sunViewProj` (shadows off) or its box, grown by `sunMargin` metres (the
// shaders' offset along the normal), is beyond one side of the map's clip
// square or its far plane. Neighbours in that order that are neighbours in
// the indices are merged into one range.
TerrainRanges visibleTerrainRanges(const TerrainChunks& chunks, const glm::mat4& viewProj, const glm::vec3& eye,
                                   const std::optional<glm::mat4>& sunViewProj, float sunMargin);

} // namespace pf
