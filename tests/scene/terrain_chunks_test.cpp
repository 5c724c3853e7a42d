#include "engine/scene/terrain_chunks.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
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
    uint32_t next = 0;
    for (const pf::TerrainChunk& chunk : chunks.chunks) {
        EXPECT_EQ(chunk.firstIndex, next);
        next += chunk.indexCount;
        for (uint32_t i = chunk.firstIndex; i < chunk.firstIndex + chunk.indexCount; ++i) {
            const glm::vec3& p = mesh.positions[chunks.indices[i]];
            EXPECT_TRUE(glm::all(glm::lessThanEqual(chunk.boxMin, p)) && glm::all(glm::lessThanEqual(p, chunk.boxMax)));
        }
    }
    // The full-detail triangles first, the coarse ones after them.
    EXPECT_EQ(cellsOf({chunks.indices.begin(), chunks.indices.begin() + next}), cellsOf(mesh.indices));
    EXPECT_EQ(next, chunks.chunks[0].coarseFirstIndex);
    EXPECT_EQ(chunks.chunks[0].indexCount, 6u * 16 * 16);
    EXPECT_EQ(chunks.chunks[8].indexCount, 6u * 5 * 5);
}

TEST(TerrainChunks, RejectBadGridsAndChunkSizes) {
    const pf::Heightfield ground = rollingGround(9);
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(ground);
    EXPECT_THROW(pf::makeTerrainChunks(mesh, ground.resolution, 0), std::invalid_argument);
    EXPECT_THROW(pf::makeTerrainChunks(mesh, ground.resolution + 1, 4), std::invalid_argument);
}

// A 60° field of view 720 pixels high.
const float kPixelsPerRadian = 360.0f / std::tan(glm::radians(30.0f));

glm::mat4 viewProjFrom(const glm::vec3& eye, const glm::vec3& target) {
    glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 2000.0f);
    return proj * glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
}

uint32_t drawnIndices(const std::vector<pf::IndexRange>& ranges) {
    uint32_t n = 0;
    for (const pf::IndexRange& r : ranges) n += r.indexCount;
    return n;
}

bool inRange(const pf::IndexRange& r, uint32_t index) {
    return r.firstIndex <= index && index < r.firstIndex + r.indexCount;
}

// How many times each chunk's triangles are drawn, at either detail; throws
// when a range holds part of a chunk.
std::vector<int> timesDrawn(const pf::TerrainChunks& chunks, const std::vector<pf::IndexRange>& ranges) {
    std::vector<int> times(chunks.chunks.size(), 0);
    uint32_t covered = 0;
    for (size_t c = 0; c < chunks.chunks.size(); ++c) {
        const pf::TerrainChunk& chunk = chunks.chunks[c];
        const bool coarse = chunk.coarseFirstIndex != chunk.firstIndex;
        for (const pf::IndexRange& r : ranges) {
            if (inRange(r, chunk.firstIndex)) times[c]++, covered += chunk.indexCount;
            if (coarse && inRange(r, chunk.coarseFirstIndex)) times[c]++, covered += chunk.coarseIndexCount;
        }
    }
    if (covered != drawnIndices(ranges)) throw std::logic_error("a range ends inside a chunk");
    return times;
}

bool holds(const std::vector<pf::IndexRange>& ranges, const pf::TerrainChunk& chunk) {
    return std::any_of(ranges.begin(), ranges.end(), [&](const pf::IndexRange& r) {
        return inRange(r, chunk.firstIndex) || inRange(r, chunk.coarseFirstIndex);
    });
}

TEST(TerrainChunks, AViewFromAboveDrawsEveryChunkOnce) {
    const pf::Heightfield ground = rollingGround(65);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    std::vector<pf::IndexRange> ranges = pf::visibleTerrainRanges(chunks, viewProjFrom({0, 800, 1}, {0, 0, 0}),
                                                                  {0, 800, 1}, kPixelsPerRadian, std::nullopt, 0.0f)
                                             .sunlit;
    const std::vector<int> times = timesDrawn(chunks, ranges);
    EXPECT_TRUE(std::all_of(times.begin(), times.end(), [](int n) { return n == 1; }));
}

TEST(TerrainChunks, AViewAlongTheGroundLeavesOutWhatIsBehindAndDrawsNearestFirst) {
    const pf::Heightfield ground = rollingGround(65);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    // From the -x edge looking toward +x, 30 m up: the ground behind the
    // eye (x < -100) is empty, and the chunks of +x must be drawn, the ones
    // under the eye first.
    const glm::vec3 eye(-60, 30, 0);
    const std::vector<pf::IndexRange> ranges =
        pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {100, 0, 0}), eye, kPixelsPerRadian, std::nullopt, 0.0f)
            .sunlit;
    ASSERT_FALSE(ranges.empty());
    const std::vector<int> times = timesDrawn(chunks, ranges);
    EXPECT_TRUE(std::any_of(times.begin(), times.end(), [](int n) { return n == 0; }));
    float previous = -1.0f;
    for (const pf::IndexRange& r : ranges) {
        const auto chunk = std::find_if(chunks.chunks.begin(), chunks.chunks.end(), [&](const pf::TerrainChunk& c) {
            return c.firstIndex == r.firstIndex || c.coarseFirstIndex == r.firstIndex;
        });
        ASSERT_NE(chunk, chunks.chunks.end());
        const float distance = glm::length(glm::clamp(eye, chunk->boxMin, chunk->boxMax) - eye);
        EXPECT_GE(distance, previous);
        previous = distance;
    }
    // The far +x column of chunks is in front of the eye: drawn.
    const pf::TerrainChunk& ahead = chunks.chunks[3 * 4 + 3]; // rows of z, 4 chunks a side
    EXPECT_TRUE(holds(ranges, ahead));
    // Looking the other way leaves out those same chunks.
    const std::vector<pf::IndexRange> back = pf::visibleTerrainRanges(chunks, viewProjFrom({90, 30, 0}, {300, 0, 0}),
                                                                      {90, 30, 0}, kPixelsPerRadian, std::nullopt, 0.0f)
                                                 .sunlit;
    EXPECT_FALSE(holds(back, chunks.chunks[0]));
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
    const pf::TerrainRanges ranges =
        pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {0, 0, 0}), eye, kPixelsPerRadian, sun, 0.5f);
    const pf::TerrainChunk& under = chunks.chunks[2 * 4 + 2]; // x, z in [0, 50]
    const pf::TerrainChunk& far = chunks.chunks[0];           // x, z in [-100, -50]
    EXPECT_TRUE(holds(ranges.shadowed, under));
    EXPECT_FALSE(holds(ranges.sunlit, under));
    EXPECT_TRUE(holds(ranges.sunlit, far));
    EXPECT_FALSE(holds(ranges.shadowed, far));
    std::vector<pf::IndexRange> both = ranges.shadowed;
    both.insert(both.end(), ranges.sunlit.begin(), ranges.sunlit.end());
    const std::vector<int> times = timesDrawn(chunks, both);
    EXPECT_TRUE(std::all_of(times.begin(), times.end(), [](int n) { return n == 1; }));
    // With shadows off every chunk is sunlit.
    EXPECT_TRUE(
        pf::visibleTerrainRanges(chunks, viewProjFrom(eye, {0, 0, 0}), eye, kPixelsPerRadian, std::nullopt, 0.5f)
            .shadowed.empty());
}

// The samples of chunk (cx, cz) of `cells` cells a side, by their index.
struct ChunkSamples {
    uint32_t x0, x1, z0, z1;
    bool onBorder(uint32_t ix, uint32_t iz) const { return ix == x0 || ix == x1 || iz == z0 || iz == z1; }
};

// Twice the signed area, in grid units, of triangle (a, b, c) seen from
// above; the fine cells' triangles are negative (counter-clockwise with +z
// down the page).
int twiceArea(uint32_t resolution, uint32_t a, uint32_t b, uint32_t c) {
    const int ax = int(a % resolution), az = int(a / resolution);
    const int bx = int(b % resolution), bz = int(b / resolution);
    const int cx = int(c % resolution), cz = int(c / resolution);
    return (bx - ax) * (cz - az) - (bz - az) * (cx - ax);
}

TEST(TerrainChunks, CoarseChunksCoverTheirSquareWithAThirdOfTheTrianglesAndKeepEverySampleOfTheirSides) {
    const pf::Heightfield ground = rollingGround(38); // chunks of 16, 16 and 5 cells a side
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(ground);
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(mesh, ground.resolution, 16);
    const uint32_t n = ground.resolution;
    EXPECT_NEAR(chunks.cellSize, ground.spacing(), 1e-4f);
    // The fine triangles' winding, from the first cell.
    const int fineSign = twiceArea(n, chunks.indices[0], chunks.indices[1], chunks.indices[2]) < 0 ? -1 : 1;
    for (uint32_t cz = 0; cz < 3; ++cz)
        for (uint32_t cx = 0; cx < 3; ++cx) {
            const pf::TerrainChunk& chunk = chunks.chunks[cz * 3 + cx];
            const ChunkSamples square{cx * 16, std::min(37u, cx * 16 + 16), cz * 16, std::min(37u, cz * 16 + 16)};
            if (cx == 2 || cz == 2) { // 5 cells: none of its own
                EXPECT_EQ(chunk.coarseFirstIndex, chunk.firstIndex);
                EXPECT_EQ(chunk.coarseIndexCount, chunk.indexCount);
                EXPECT_EQ(chunk.coarseError, 0.0f);
                continue;
            }
            ASSERT_GE(chunk.coarseFirstIndex, chunks.chunks.back().firstIndex + chunks.chunks.back().indexCount);
            // 6 × 6 inner blocks of two triangles, 24 side blocks of three, 4 corners of four.
            EXPECT_EQ(chunk.coarseIndexCount, 3u * (72 + 72 + 16));
            int area = 0;
            std::vector<bool> used(size_t(n) * n, false);
            for (uint32_t i = chunk.coarseFirstIndex; i < chunk.coarseFirstIndex + chunk.coarseIndexCount; i += 3) {
                const uint32_t* t = &chunks.indices[i];
                const int a = twiceArea(n, t[0], t[1], t[2]);
                EXPECT_EQ(a < 0 ? -1 : 1, fineSign) << "triangle " << (i - chunk.coarseFirstIndex) / 3;
                EXPECT_NE(a, 0);
                area += a;
                for (int k = 0; k < 3; ++k) used[t[k]] = true;
            }
            EXPECT_EQ(area, fineSign * 2 * 16 * 16); // the chunk's square exactly (no triangle overlaps: same winding)
            for (uint32_t iz = square.z0; iz <= square.z1; ++iz)
                for (uint32_t ix = square.x0; ix <= square.x1; ++ix) {
                    const bool even = (ix - square.x0) % 2 == 0 && (iz - square.z0) % 2 == 0;
                    EXPECT_EQ(used[iz * n + ix], even || square.onBorder(ix, iz)) << ix << ", " << iz;
                }
        }
}

// Where the coarse mesh lies at (ix, iz): the plane of the coarse triangle
// of `chunk` that holds the sample (barycentric in grid units).
float coarseHeightAt(const pf::TerrainMesh& mesh, uint32_t resolution, const pf::TerrainChunks& chunks,
                     const pf::TerrainChunk& chunk, uint32_t ix, uint32_t iz) {
    const uint32_t p = iz * resolution + ix;
    for (uint32_t i = chunk.coarseFirstIndex; i < chunk.coarseFirstIndex + chunk.coarseIndexCount; i += 3) {
        const uint32_t* t = &chunks.indices[i];
        const int area = twiceArea(resolution, t[0], t[1], t[2]);
        const int wa = twiceArea(resolution, p, t[1], t[2]), wb = twiceArea(resolution, t[0], p, t[2]);
        const int wc = area - wa - wb;
        const bool inside = area < 0 ? (wa <= 0 && wb <= 0 && wc <= 0) : (wa >= 0 && wb >= 0 && wc >= 0);
        if (inside)
            return (float(wa) * mesh.positions[t[0]].y + float(wb) * mesh.positions[t[1]].y +
                    float(wc) * mesh.positions[t[2]].y) /
                   float(area);
    }
    throw std::logic_error("a sample outside the coarse chunk");
}

TEST(TerrainChunks, TheCoarseErrorIsTheFarthestSampleFromTheCoarseMeshAndNoneForAPlane) {
    for (const bool plane : {false, true}) {
        pf::Heightfield ground = rollingGround(33);
        if (plane)
            for (uint32_t iz = 0; iz < ground.resolution; ++iz)
                for (uint32_t ix = 0; ix < ground.resolution; ++ix)
                    ground.heights[iz * ground.resolution + ix] = 0.25f * float(ix) - 0.5f * float(iz);
        const pf::TerrainMesh mesh = pf::makeTerrainMesh(ground);
        const pf::TerrainChunks chunks = pf::makeTerrainChunks(mesh, ground.resolution, 16);
        for (uint32_t c = 0; c < 4; ++c) {
            const pf::TerrainChunk& chunk = chunks.chunks[c];
            float farthest = 0.0f;
            for (uint32_t iz = (c / 2) * 16; iz <= (c / 2) * 16 + 16; ++iz)
                for (uint32_t ix = (c % 2) * 16; ix <= (c % 2) * 16 + 16; ++ix)
                    farthest =
                        std::max(farthest, std::abs(ground.height(ix, iz) -
                                                    coarseHeightAt(mesh, ground.resolution, chunks, chunk, ix, iz)));
            EXPECT_NEAR(chunk.coarseError, farthest, 1e-5f) << "chunk " << c;
            if (plane)
                EXPECT_LT(chunk.coarseError, 1e-5f);
            else
                EXPECT_GT(chunk.coarseError, 0.01f);
        }
    }
}

// Whether the chunk is drawn by its coarse triangles.
bool drawnCoarse(const std::vector<pf::IndexRange>& ranges, const pf::TerrainChunk& chunk) {
    return std::any_of(ranges.begin(), ranges.end(),
                       [&](const pf::IndexRange& r) { return inRange(r, chunk.coarseFirstIndex); });
}

TEST(TerrainChunks, AChunkIsDrawnCoarseWhereItsErrorAndItsCellsAreSmallOnScreen) {
    const pf::Heightfield ground = rollingGround(129); // 200 m, 1.5625 m cells, 8 × 8 chunks
    const pf::TerrainChunks chunks = pf::makeTerrainChunks(pf::makeTerrainMesh(ground), ground.resolution, 16);
    const glm::vec3 eye(-110, 20, 0); // beyond the -x edge, looking along +x
    const glm::mat4 viewProj = viewProjFrom(eye, {100, 0, 0});
    const std::vector<pf::IndexRange> ranges =
        pf::visibleTerrainRanges(chunks, viewProj, eye, kPixelsPerRadian, std::nullopt, 0.0f).sunlit;
    const std::vector<int> times = timesDrawn(chunks, ranges);
    int coarse = 0, fine = 0;
    for (size_t c = 0; c < chunks.chunks.size(); ++c) {
        if (times[c] == 0) continue;
        const pf::TerrainChunk& chunk = chunks.chunks[c];
        const float distance = glm::length(glm::clamp(eye, chunk.boxMin, chunk.boxMax) - eye);
        const bool small = chunk.coarseError * kPixelsPerRadian / distance < pf::kCoarseErrorPixels &&
                           chunks.cellSize * kPixelsPerRadian / distance < pf::kCoarseCellPixels;
        EXPECT_EQ(drawnCoarse(ranges, chunk), small) << "chunk " << c << " at " << distance << " m";
        (small ? coarse : fine)++;
    }
    // This view has both: the near columns in full, the far ones coarse.
    EXPECT_GT(coarse, 0);
    EXPECT_GT(fine, 0);
    EXPECT_FALSE(drawnCoarse(ranges, chunks.chunks[4 * 8]));    // the -x column, under the eye
    EXPECT_TRUE(drawnCoarse(ranges, chunks.chunks[4 * 8 + 7])); // the +x column, 200 m on
    // Twice the pixels a radian (a view twice as tall): fewer coarse chunks.
    const std::vector<pf::IndexRange> sharper =
        pf::visibleTerrainRanges(chunks, viewProj, eye, 2.0f * kPixelsPerRadian, std::nullopt, 0.0f).sunlit;
    int sharperCoarse = 0;
    for (const pf::TerrainChunk& chunk : chunks.chunks) sharperCoarse += drawnCoarse(sharper, chunk);
    EXPECT_LT(sharperCoarse, coarse);
}

} // namespace
