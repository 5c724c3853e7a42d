#include "engine/scene/terrain_chunks.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace pf {

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
            out.chunks.push_back(chunk);
        }
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

void append(std::vector<IndexRange>& ranges, const TerrainChunk& chunk) {
    if (!ranges.empty() && ranges.back().firstIndex + ranges.back().indexCount == chunk.firstIndex)
        ranges.back().indexCount += chunk.indexCount;
    else
        ranges.push_back({chunk.firstIndex, chunk.indexCount});
}

} // namespace

TerrainRanges visibleTerrainRanges(const TerrainChunks& chunks, const glm::mat4& viewProj, const glm::vec3& eye,
                                   const std::optional<glm::mat4>& sunViewProj, float sunMargin) {
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
        append(sunlit ? ranges.sunlit : ranges.shadowed, *chunk);
    }
    return ranges;
}

} // namespace pf
