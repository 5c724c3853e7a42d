// Bump profiles and their superposition on a height grid
// (lsystem/landscape/terrain_bumps.h).
#include "lsystem/landscape/terrain_bumps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace lsys::landscape {
namespace {

constexpr BumpShape kShapes[] = {BumpShape::Hill, BumpShape::Peak, BumpShape::Mesa, BumpShape::Valley};

TEST(BumpProfile, EveryShapeIsOneAtItsCentreAndZeroFromItsRim) {
    for (BumpShape shape : kShapes) {
        SCOPED_TRACE(std::string(bumpShapeName(shape)));
        EXPECT_FLOAT_EQ(bumpProfile(shape, 0.0f), 1.0f);
        EXPECT_FLOAT_EQ(bumpProfile(shape, 1.0f), 0.0f);
        EXPECT_FLOAT_EQ(bumpProfile(shape, 3.0f), 0.0f);
        for (float t = 0.05f; t < 1.0f; t += 0.05f) { // falls from the centre to the rim
            EXPECT_LE(bumpProfile(shape, t), bumpProfile(shape, t - 0.05f));
            EXPECT_GT(bumpProfile(shape, t), 0.0f);
        }
    }
}

TEST(BumpProfile, TheHillIsARaisedCosine) {
    EXPECT_NEAR(bumpProfile(BumpShape::Hill, 0.5f), 0.5f, 1e-6f);
    EXPECT_NEAR(bumpProfile(BumpShape::Hill, 0.25f), 0.5f * (1.0f + std::sqrt(0.5f)), 1e-6f);
    // Level at the top: the first step away from the centre barely drops.
    EXPECT_GT(bumpProfile(BumpShape::Hill, 0.01f), 0.999f);
}

TEST(BumpProfile, ThePeakIsPointed) {
    EXPECT_NEAR(bumpProfile(BumpShape::Peak, 0.5f), 0.25f, 1e-6f);
    // Sharp at the top: the first step away from the centre drops twice as fast as it goes.
    EXPECT_NEAR(bumpProfile(BumpShape::Peak, 0.01f), 0.9801f, 1e-6f);
}

TEST(BumpProfile, TheMesaIsFlatToHalfItsRadius) {
    EXPECT_FLOAT_EQ(bumpProfile(BumpShape::Mesa, 0.3f), 1.0f);
    EXPECT_FLOAT_EQ(bumpProfile(BumpShape::Mesa, 0.5f), 1.0f);
    EXPECT_NEAR(bumpProfile(BumpShape::Mesa, 0.75f), 0.5f, 1e-6f);
}

TEST(BumpProfile, TheValleyHasTheHillsProfile) {
    for (float t = 0.0f; t <= 1.0f; t += 0.1f)
        EXPECT_EQ(bumpProfile(BumpShape::Valley, t), bumpProfile(BumpShape::Hill, t));
}

// A 5 m grid of 41² samples over 200 m: sample (20, 20) is the origin.
struct Grid {
    uint32_t resolution = 41;
    float size = 200.0f;
    std::vector<float> heights = std::vector<float>(41 * 41, 0.0f);
    float at(uint32_t ix, uint32_t iz) const { return heights[iz * resolution + ix]; }
};

TEST(AddBumps, AHillIsItsHeightAtItsCentreAndZeroBeyondItsRadius) {
    Grid grid;
    const TerrainBump hill{10.0f, -20.0f, 30.0f, 25.0f, BumpShape::Hill};
    addBumps(grid.heights, grid.resolution, grid.size, std::span(&hill, 1));
    EXPECT_FLOAT_EQ(grid.at(22, 16), 30.0f); // x 10, z -20
    EXPECT_NEAR(grid.at(22 + 3, 16), 30.0f * bumpProfile(BumpShape::Hill, 15.0f / 25.0f), 1e-5f);
    for (uint32_t iz = 0; iz < grid.resolution; ++iz)
        for (uint32_t ix = 0; ix < grid.resolution; ++ix) {
            const float x = -100.0f + 5.0f * float(ix), z = -100.0f + 5.0f * float(iz);
            if (std::hypot(x - 10.0f, z + 20.0f) >= 25.0f) {
                EXPECT_EQ(grid.at(ix, iz), 0.0f) << ix << ", " << iz;
            }
        }
}

TEST(AddBumps, BumpsAddAndValleysDig) {
    const TerrainBump hill{0.0f, 0.0f, 20.0f, 40.0f, BumpShape::Hill};
    const TerrainBump peak{10.0f, 5.0f, 12.0f, 30.0f, BumpShape::Peak};
    const TerrainBump valley{-15.0f, 0.0f, -8.0f, 20.0f, BumpShape::Valley};
    Grid together, apart[3];
    const TerrainBump all[] = {hill, peak, valley};
    addBumps(together.heights, together.resolution, together.size, all);
    for (int i = 0; i < 3; ++i) addBumps(apart[i].heights, apart[i].resolution, apart[i].size, std::span(&all[i], 1));
    for (size_t s = 0; s < together.heights.size(); ++s)
        EXPECT_NEAR(together.heights[s], apart[0].heights[s] + apart[1].heights[s] + apart[2].heights[s], 1e-5f);
    EXPECT_FLOAT_EQ(apart[2].at(17, 20), -8.0f); // the valley's centre, x -15
    EXPECT_LT(together.at(17, 20), apart[0].at(17, 20));
    EXPECT_FLOAT_EQ(bumpsHeightAt(all, 10.0f, 5.0f), bumpHeightAt(hill, 10.0f, 5.0f) + 12.0f);
}

TEST(AddBumps, BumpsPastTheEdgeAddOnlyTheirInsidePart) {
    Grid grid;
    const TerrainBump edge{105.0f, 0.0f, 10.0f, 20.0f, BumpShape::Mesa}; // centre outside the square
    const TerrainBump away{400.0f, 400.0f, 10.0f, 20.0f, BumpShape::Hill};
    const TerrainBump both[] = {edge, away};
    addBumps(grid.heights, grid.resolution, grid.size, both);
    EXPECT_FLOAT_EQ(grid.at(40, 20), 10.0f); // x 100: within the mesa's flat top
    EXPECT_EQ(grid.at(36, 20), 0.0f);        // x 80: 25 m from its centre
    EXPECT_EQ(grid.at(40, 40), 0.0f);
}

TEST(AddBumps, ItsCostIsTheSamplesInTheBumpsBoundingSquares) {
    const Grid grid;
    const TerrainBump hill{10.0f, -20.0f, 30.0f, 25.0f, BumpShape::Hill}; // x 85…135 m, z 55…105 m from the corner
    const TerrainBump wide{0.0f, 0.0f, 1.0f, 1e6f, BumpShape::Hill};
    const TerrainBump away{400.0f, 400.0f, 10.0f, 20.0f, BumpShape::Hill};
    EXPECT_EQ(bumpSamples(grid.resolution, grid.size, std::span(&hill, 1)), 11u * 11u);
    EXPECT_EQ(bumpSamples(grid.resolution, grid.size, std::span(&wide, 1)), 41u * 41u);
    EXPECT_EQ(bumpSamples(grid.resolution, grid.size, std::span(&away, 1)), 0u);
    const TerrainBump three[] = {hill, wide, away};
    EXPECT_EQ(bumpSamples(grid.resolution, grid.size, three), 11u * 11u + 41u * 41u);
}

TEST(AddBumps, BumpsCoveringTooManySamplesAreRefusedBeforeAnyIsAdded) {
    Grid grid;
    const TerrainBump wide{0.0f, 0.0f, 1.0f, 1e6f, BumpShape::Hill};
    const std::vector<TerrainBump> bumps(kMaxBumpSamples / (41 * 41) + 1, wide);
    try {
        addBumps(grid.heights, grid.resolution, grid.size, bumps);
        FAIL() << "no MountainError";
    } catch (const MountainError& error) {
        EXPECT_NE(std::string(error.what()).find("more than 1073741824"), std::string::npos) << error.what();
    }
    EXPECT_EQ(grid.heights, Grid{}.heights);
    // One bump fewer is within the limit (not added here: a billion evaluations take seconds).
    EXPECT_LE(bumpSamples(grid.resolution, grid.size, std::span(bumps.data(), bumps.size() - 1)), kMaxBumpSamples);
}

TEST(AddBumps, TheSameBumpsGiveTheSameHeightsBitForBit) {
    std::vector<TerrainBump> bumps;
    for (int i = 0; i < 50; ++i)
        bumps.push_back({float(i * 7 % 90) - 45.0f, float(i * 13 % 80) - 40.0f, float(i % 9) - 3.0f,
                         8.0f + float(i % 5) * 3.0f, kShapes[i % 4]});
    Grid first, second;
    addBumps(first.heights, first.resolution, first.size, bumps);
    addBumps(second.heights, second.resolution, second.size, bumps);
    EXPECT_EQ(first.heights, second.heights);
    EXPECT_NE(first.heights, Grid{}.heights);
}

} // namespace
} // namespace lsys::landscape
