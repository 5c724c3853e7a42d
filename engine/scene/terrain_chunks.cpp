#include "engine/scene/terrain_chunks.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pf {

namespace {

// A sample of the grid, by column and row.
struct Sample {
    uint32_t ix, iz;
};

// The coarse triangles of the chunk [x0, x1) × [z0, z1) (an even number of
// cells, at least 4, a side) appended to `indices`; returns their coarseError.
// Each 2 × 2 block of cells is one coarse cell: two triangles split along
// the same diagonal as the cells' own, or, on the chunk's sides, a fan over
// its corners and the middle samples of its sides on the chunk's border,
// from a corner on neither of those sides (there is one: a block touches
// at most two neighbouring sides of a chunk 4 cells or more across).
float appendCoarseChunk(const TerrainMesh& mesh, uint32_t resolution, uint32_t x0, uint32_t x1, uint32_t z0,
                        uint32_t z1, std::vector<uint32_t>& indices) {
    const auto id = [&](Sample s) { return s.iz * resolution + s.ix; };
    float error = 0.0f;
    // The largest vertical distance of the samples of the triangle's block
    // from its plane, over those inside it (barycentric in grid units, exact).
    const auto measure = [&](Sample a, Sample b, Sample c, uint32_t bx, uint32_t bz) {
        const auto cross = [](int ux, int uz, int vx, int vz) { return ux * vz - uz * vx; };
        const int area =
            cross(int(b.ix) - int(a.ix), int(b.iz) - int(a.iz), int(c.ix) - int(a.ix), int(c.iz) - int(a.iz));
        for (uint32_t iz = bz; iz <= bz + 2; ++iz)
            for (uint32_t ix = bx; ix <= bx + 2; ++ix) {
                const int wa =
                    cross(int(b.ix) - int(ix), int(b.iz) - int(iz), int(c.ix) - int(ix), int(c.iz) - int(iz));
                const int wb =
                    cross(int(c.ix) - int(ix), int(c.iz) - int(iz), int(a.ix) - int(ix), int(a.iz) - int(iz));
                const int wc = area - wa - wb;
                if ((wa < 0 || wb < 0 || wc < 0) && (wa > 0 || wb > 0 || wc > 0)) continue; // outside
                const float plane = (float(wa) * mesh.positions[id(a)].y + float(wb) * mesh.positions[id(b)].y +
                                     float(wc) * mesh.positions[id(c)].y) /
                                    float(area);
                error = std::max(error, std::abs(mesh.positions[id({ix, iz})].y - plane));
            }
    };
    for (uint32_t z = z0; z < z1; z += 2)
        for (uint32_t x = x0; x < x1; x += 2) {
            // The block's outline counter-clockwise seen from above (+z down
            // the page): down its -x side, along +z, up +x, back along -z;
            // each side's middle sample kept where it is the chunk's border.
            const bool split[4] = {x == x0, z + 2 == z1, x + 2 == x1, z == z0};
            const Sample corners[4] = {{x, z}, {x, z + 2}, {x + 2, z + 2}, {x + 2, z}};
            const Sample middles[4] = {{x, z + 1}, {x + 1, z + 2}, {x + 2, z + 1}, {x + 1, z}};
            // Corner k starts side k and ends side k − 1. The last corner
            // first: without split sides that is the cells' own diagonal.
            int apex = -1;
            for (int k : {3, 1, 0, 2})
                if (apex < 0 && !split[k] && !split[(k + 3) % 4]) apex = k;
            std::vector<Sample> outline;
            for (int i = 0; i < 4; ++i) {
                const int k = (apex + i) % 4;
                outline.push_back(corners[k]);
                if (split[k]) outline.push_back(middles[k]);
            }
            for (size_t i = 1; i + 1 < outline.size(); ++i) {
                indices.insert(indices.end(), {id(outline[0]), id(outline[i]), id(outline[i + 1])});
                measure(outline[0], outline[i], outline[i + 1], x, z);
            }
        }
    return error;
}

} // namespace

TerrainChunks makeTerrainChunks(const TerrainMesh& mesh, uint32_t resolution, uint32_t cellsPerChunk) {
    if (cellsPerChunk == 0) throw std::invalid_argument("terrain chunks need at least one cell a side");
    if (resolution < 2 || mesh.positions.size() != size_t(resolution) * resolution)
        throw std::invalid_argument("terrain chunks need a square grid of vertices");
    const uint32_t cells = resolution - 1;
    const uint32_t perSide = (cells + cellsPerChunk - 1) / cellsPerChunk;
    TerrainChunks out;
    out.indices.reserve(size_t(6) * cells * cells);
    for (uint32_t cz = 0; cz < perSide; ++cz)
        for (uint32_t cx = 0; cx < perSide; ++cx) {
            TerrainChunk chunk;
            chunk.firstIndex = uint32_t(out.indices.size());
            chunk.boxMin = glm::vec3(std::numeric_limits<float>::max());
            chunk.boxMax = glm::vec3(-std::numeric_limits<float>::max());
            const uint32_t x0 = cx * cellsPerChunk, x1 = std::min(cells, x0 + cellsPerChunk);
            const uint32_t z0 = cz * cellsPerChunk, z1 = std::min(cells, z0 + cellsPerChunk);
            for (uint32_t iz = z0; iz < z1; ++iz)
                for (uint32_t ix = x0; ix < x1; ++ix) {
                    // The cell's indices as makeTerrainMesh writes them.
                    const size_t cell = size_t(iz) * cells + ix;
                    out.indices.insert(out.indices.end(), mesh.indices.begin() + 6 * cell,
                                       mesh.indices.begin() + 6 * (cell + 1));
                }
            for (uint32_t iz = z0; iz <= z1; ++iz)
                for (uint32_t ix = x0; ix <= x1; ++ix) {
                    const glm::vec3& p = mesh.positions[size_t(iz) * resolution + ix];
                    chunk.boxMin = glm::min(chunk.boxMin, p);
                    chunk.boxMax = glm::max(chunk.boxMax, p);
                }
            chunk.indexCount = uint32_t(out.indices.size()) - chunk.firstIndex;
            chunk.coarseFirstIndex = chunk.firstIndex;
            chunk.coarseIndexCount = chunk.indexCount;
            out.chunks.push_back(chunk);
        }
    for (uint32_t cz = 0; cz < perSide; ++cz)
        for (uint32_t cx = 0; cx < perSide; ++cx) {
            TerrainChunk& chunk = out.chunks[cz * perSide + cx];
            const uint32_t x0 = cx * cellsPerChunk, x1 = std::min(cells, x0 + cellsPerChunk);
            const uint32_t z0 = cz * cellsPerChunk, z1 = std::min(cells, z0 + cellsPerChunk);
            const auto coarsens = [](uint32_t n) { return n >= 4 && n % 2 == 0; };
            if (!coarsens(x1 - x0) || !coarsens(z1 - z0)) continue;
            chunk.coarseFirstIndex = uint32_t(out.indices.size());
            chunk.coarseError = appendCoarseChunk(mesh, resolution, x0, x1, z0, z1, out.indices);
            chunk.coarseIndexCount = uint32_t(out.indices.size()) - chunk.coarseFirstIndex;
        }
    out.cellSize = mesh.positions[1].x - mesh.positions[0].x;
    return out;
}

namespace {

// Whether every corner of the box (grown by `margin`) is beyond one of the
// clip planes x = ±w, y = ±w, z = w, or z = 0 when `nearPlane`.
bool beyondAPlane(const glm::vec3& boxMin, const glm::vec3& boxMax, const glm::mat4& viewProj, bool nearPlane) {
    glm::vec4 corners[8];
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? boxMax.x : boxMin.x, (i & 2) ? boxMax.y : boxMin.y, (i & 4) ? boxMax.z : boxMin.z);
        corners[i] = viewProj * glm::vec4(p, 1.0f);
    }
    auto allBeyond = [&](auto beyond) { return std::all_of(corners, corners + 8, beyond); };
    return allBeyond([](const glm::vec4& c) { return c.x < -c.w; }) ||
           allBeyond([](const glm::vec4& c) { return c.x > c.w; }) ||
           allBeyond([](const glm::vec4& c) { return c.y < -c.w; }) ||
           allBeyond([](const glm::vec4& c) { return c.y > c.w; }) ||
           allBeyond([](const glm::vec4& c) { return c.z > c.w; }) ||
           (nearPlane && allBeyond([](const glm::vec4& c) { return c.z < 0.0f; }));
}

float distanceToBox(const TerrainChunk& chunk, const glm::vec3& eye) {
    return glm::length(glm::clamp(eye, chunk.boxMin, chunk.boxMax) - eye);
}

void append(std::vector<IndexRange>& ranges, IndexRange range) {
    if (!ranges.empty() && ranges.back().firstIndex + ranges.back().indexCount == range.firstIndex)
        ranges.back().indexCount += range.indexCount;
    else
        ranges.push_back(range);
}

// The chunk's indices at the detail its distance calls for (kCoarseErrorPixels).
IndexRange detailOf(const TerrainChunk& chunk, float cellSize, float distance, float pixelsPerRadian) {
    const float coarseCell = std::max(chunk.coarseError / kCoarseErrorPixels, cellSize / kCoarseCellPixels);
    if (coarseCell * pixelsPerRadian < distance) return {chunk.coarseFirstIndex, chunk.coarseIndexCount};
    return {chunk.firstIndex, chunk.indexCount};
}

} // namespace

TerrainRanges visibleTerrainRanges(const TerrainChunks& chunks, const glm::mat4& viewProj, const glm::vec3& eye,
                                   float pixelsPerRadian, const std::optional<glm::mat4>& sunViewProj,
                                   float sunMargin) {
    std::vector<const TerrainChunk*> seen;
    for (const TerrainChunk& chunk : chunks.chunks)
        if (chunk.indexCount > 0 && !beyondAPlane(chunk.boxMin, chunk.boxMax, viewProj, true)) seen.push_back(&chunk);
    // Ties (the eye above several boxes) in index order, so the ranges are
    // the same on every run.
    std::stable_sort(seen.begin(), seen.end(), [&](const TerrainChunk* a, const TerrainChunk* b) {
        return distanceToBox(*a, eye) < distanceToBox(*b, eye);
    });
    TerrainRanges ranges;
    const glm::vec3 margin(sunMargin);
    for (const TerrainChunk* chunk : seen) {
        const bool sunlit =
            !sunViewProj || beyondAPlane(chunk->boxMin - margin, chunk->boxMax + margin, *sunViewProj, false);
        append(sunlit ? ranges.sunlit : ranges.shadowed,
               detailOf(*chunk, chunks.cellSize, distanceToBox(*chunk, eye), pixelsPerRadian));
    }
    return ranges;
}

} // namespace pf
