#include "engine/scene/terrain_chunks.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <stdexcept>

namespace {

pf::Heightfield rollingGround(uint32_t resolution) {
    pf::NoiseTerrainSettings settings;
    settings.resolution = resolution;
    settings.size = 200;
    settings.seed = 5;
    return pf::makeNoiseTerrain(settings);
}

// Every cell's two triangles, as makeTerrainMesh writes them, once.
std::vector<std::array<uint32_t, 6>> cellsOf(const std::vector<uint32_t>& indices) {
    std::vector<std::array<uint32_t, 6>> cells(indices.size() / 6);
    for (size_t c = 0; c < cells.size(); ++c) std::copy_n(indices.begin() + 6 * c, 6, cells[c].begin());
    std::sort(cells.begin(), cells.end());
    return cells;
}

TEST(TerrainChunks, HoldEveryCellOfTheMeshOnceWithBoxesAroundTheirVertices) {
    const pf::Heightfield ground = rollingGround(38); // 37 cells a side: chunks of 16, 16 and 5
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(ground);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(mesh, ground.resolution, 16);
    ASSERT_EQ(chunks.chunks.size(), 9u);
    EXPECT_EQ(cellsOf(chunks.indices), cellsOf(mesh.indices));
    uint32_t next = 0;
    for (const pf::TerrainChunk& chunk : chunks.chunks) {
        EXPECT_EQ(chunk.firstIndex, next);
        next += chunk.indexCount;
        for (uint32_t i = chunk.firstIndex; i < chunk.firstIndex + chunk.indexCount; ++i) {
            const glm::vec3& p = mesh.positions[chunks.indices[i]];
            EXPECT_TRUE(glm::all(glm::lessThanEqual(chunk.boxMin, p)) && glm::all(glm::lessThanEqual(p, chunk.boxMax)));
        }
    }
    EXPECT_EQ(next, chunks.indices.size());
    EXPECT_EQ(chunks.chunks[0].indexCount, 6u * 16 * 16);
    EXPECT_EQ(chunks.chunks[8].indexCount, 6u * 5 * 5);
}

TEST(TerrainChunks, RejectBadGridsAndChunkSizes) {
    const pf::Heightfield ground = rollingGround(9);
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(ground);
    EXPECT_THROW(pf::makeTerrainChunks(mesh, ground.resolution, 0), std::invalid_argument);
    EXPECT_THROW(pf::makeTerrainChunks(mesh, ground.resolution + 1, 4), std::invalid_argument);
}

glm::mat4 viewProjFrom(const glm::vec3& eye, const glm::vec3& target) {
    glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 2000.0f);
    return proj * glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
}

uint32_t drawnIndices(const std::vector<pf::IndexRange>& ranges) {
    uint32_t n = 0;
    for (const pf::IndexRange& r : ranges) n += r.indexCount;
    return n;
}

TEST(TerrainChunks, AViewFromAboveDrawsEveryChunkOnce) {
    const pf::Heightfield ground = rollingGround(65);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    std::vector<pf::IndexRange> ranges =
        pf::visibleTerrainRanges(chunks, viewProjFrom({0, 800, 1}, {0, 0, 0}), {0, 800, 1}, std::nullopt, 0.0f).sunlit;
    std::sort(ranges.begin(), ranges.end(),
              [](const pf::IndexRange& a, const pf::IndexRange& b) { return a.firstIndex < b.firstIndex; });
    uint32_t next = 0;
    for (const pf::IndexRange& r : ranges) {
        EXPECT_EQ(r.firstIndex, next);
        next += r.indexCount;
    }
    EXPECT_EQ(next, chunks.indices.size());
}

TEST(TerrainChunks, AViewAlongTheGroundLeavesOutWhatIsBehindAndDrawsNearestFirst) {
    const pf::Heightfield ground = rollingGround(65);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    // From the -x edge looking toward +x, 30 m up: the ground behind the
    // eye (x < -100) is empty, and the chunks of +x must be drawn, the ones
    // under the eye first.
    const glm::vec3 eye(-60, 30, 0);
    const std::vector<pf::IndexRange> ranges =
        pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {100, 0, 0}), eye, std::nullopt, 0.0f).sunlit;
    ASSERT_FALSE(ranges.empty());
    EXPECT_LT(drawnIndices(ranges), chunks.indices.size());
    float previous = -1.0f;
    for (const pf::IndexRange& r : ranges) {
        const auto chunk = std::find_if(chunks.chunks.begin(), chunks.chunks.end(),
                                        [&](const pf::TerrainChunk& c) { return c.firstIndex == r.firstIndex; });
        ASSERT_NE(chunk, chunks.chunks.end());
        const float distance = glm::length(glm::clamp(eye, chunk->boxMin, chunk->boxMax) - eye);
        EXPECT_GE(distance, previous);
        previous = distance;
    }
    // The far +x column of chunks is in front of the eye: drawn.
    const pf::TerrainChunk& ahead = chunks.chunks[3 * 4 + 3]; // rows of z, 4 chunks a side
    const bool drawn = std::any_of(ranges.begin(), ranges.end(), [&](const pf::IndexRange& r) {
        return r.firstIndex <= ahead.firstIndex && ahead.firstIndex < r.firstIndex + r.indexCount;
    });
    EXPECT_TRUE(drawn);
    // Looking the other way leaves out those same chunks.
    const std::vector<pf::IndexRange> back =
        pf::visibleTerrainRanges(chunks, viewProjFrom({90, 30, 0}, {300, 0, 0}), {90, 30, 0}, std::nullopt, 0.0f)
            .sunlit;
    const bool drawnWhenBehind = std::any_of(back.begin(), back.end(), [&](const pf::IndexRange& r) {
        return r.firstIndex <= chunks.chunks[0].firstIndex && chunks.chunks[0].firstIndex < r.firstIndex + r.indexCount;
    });
    EXPECT_FALSE(drawnWhenBehind);
}

bool holds(const std::vector<pf::IndexRange>& ranges, const pf::TerrainChunk& chunk) {
    return std::any_of(ranges.begin(), ranges.end(), [&](const pf::IndexRange& r) {
        return r.firstIndex <= chunk.firstIndex && chunk.firstIndex < r.firstIndex + r.indexCount;
    });
}

TEST(TerrainChunks, OnlyChunksTheSunsMapReachesAreShadowed) {
    const pf::Heightfield ground = rollingGround(65);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    // The sun straight above a 40 m square around (30, 0, 30), depth 0…1
    // over 200 m below a point 100 m up: the chunk under it is shadowed,
    // the far corner's sunlit; every chunk is drawn once either way.
    const glm::mat4 sun = glm::orthoRH_ZO(-20.0f, 20.0f, -20.0f, 20.0f, 0.0f, 200.0f) *
                          glm::lookAtRH(glm::vec3(30, 100, 30), glm::vec3(30, 0, 30), glm::vec3(0, 0, -1));
    const glm::vec3 eye(0, 800, 1);
    const pf::TerrainRanges ranges = pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {0, 0, 0}), eye, sun, 0.5f);
    const pf::TerrainChunk& under = chunks.chunks[2 * 4 + 2]; // x, z in [0, 50]
    const pf::TerrainChunk& far = chunks.chunks[0];           // x, z in [-100, -50]
    EXPECT_TRUE(holds(ranges.shadowed, under));
    EXPECT_FALSE(holds(ranges.sunlit, under));
    EXPECT_TRUE(holds(ranges.sunlit, far));
    EXPECT_FALSE(holds(ranges.shadowed, far));
    EXPECT_EQ(drawnIndices(ranges.shadowed) + drawnIndices(ranges.sunlit), chunks.indices.size());
    // With shadows off every chunk is sunlit.
    EXPECT_TRUE(
        pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {0, 0, 0}), eye, std::nullopt, 0.5f).shadowed.empty());
}

} // namespace
