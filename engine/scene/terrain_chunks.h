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
    // The same ground with every second sample inside the chunk, every
    // sample along its sides (so it meets a neighbour of either detail
    // without a crack): about a third of the triangles. A chunk with an odd
    // number of cells or fewer than 4 on a side has none (the full range
    // again, error 0).
    uint32_t coarseFirstIndex = 0;
    uint32_t coarseIndexCount = 0;
    float coarseError = 0.0f; // metres: the largest vertical distance of the chunk's samples from the coarse mesh
};

// The mesh's triangles reordered chunk by chunk: chunk (cx, cz) holds the
// cells of columns [cx·cells, (cx+1)·cells) and rows [cz·cells, (cz+1)·cells),
// fewer at the far edges, each cell's two triangles as makeTerrainMesh
// writes them; chunks in rows of increasing z. The coarse triangles follow,
// chunk by chunk in the same order, counter-clockwise seen from above.
struct TerrainChunks {
    std::vector<uint32_t> indices;
    std::vector<TerrainChunk> chunks;
    float cellSize = 0.0f; // metres between neighbouring samples
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

// When a chunk is drawn coarse, as pixels on screen at its box's nearest
// point: its coarseError below kCoarseErrorPixels (the screen-space error of
// Ulrich 2002, "Rendering massive terrains using chunked level of detail
// control", error · pixels a radian / distance), and its cells below
// kCoarseCellPixels, so the attributes interpolated across the coarse
// triangles (normals, fog, the broad grass octave) change over a few pixels
// only. On lavapipe a far triangle of a few pixels is set up, binned and
// shaded in 4×4 blocks for those few pixels (docs/BENCHMARKS.md).
inline constexpr float kCoarseErrorPixels = 0.5f;
inline constexpr float kCoarseCellPixels = 8.0f;

// The chunks whose boxes may be seen through `viewProj` (clip space with
// Vulkan's depth 0…1; a box is left out only when all its corners are beyond
// one clip plane), nearest to `eye` first so the depth test keeps nearer
// hills from shading what they hide, each at one detail: coarse when small
// enough on screen (above) at `pixelsPerRadian` (half the viewport's height
// over the tangent of half its vertical field of view). A chunk is sunlit when
// there is no `sunViewProj` (shadows off) or its box, grown by `sunMargin`
// metres (the shaders' offset along the normal), is beyond one side of the
// map's clip square or its far plane. Neighbours in that order that are
// neighbours in the indices are merged into one range.
TerrainRanges visibleTerrainRanges(const TerrainChunks& chunks, const glm::mat4& viewProj, const glm::vec3& eye,
                                   float pixelsPerRadian, const std::optional<glm::mat4>& sunViewProj, float sunMargin);

} // namespace pf
