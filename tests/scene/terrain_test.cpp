#include "terrain_test_support.h"

#include "engine/image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

namespace {

using fieldtest::sampledTerrain;

pf::NoiseTerrainSettings smallNoise(uint64_t seed) {
    pf::NoiseTerrainSettings settings;
    settings.resolution = 65;
    settings.size = 256;
    settings.seed = seed;
    return settings;
}

TEST(NoiseTerrain, SameSeedGivesTheSameHeightsBitForBit) {
    EXPECT_EQ(pf::makeNoiseTerrain(smallNoise(7)).heights, pf::makeNoiseTerrain(smallNoise(7)).heights);
}

TEST(NoiseTerrain, DifferentSeedsGiveDifferentHeights) {
    const std::vector<float> a = pf::makeNoiseTerrain(smallNoise(7)).heights;
    const std::vector<float> b = pf::makeNoiseTerrain(smallNoise(8)).heights;
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    EXPECT_GT(differing, a.size() * 9 / 10);
}

TEST(NoiseTerrain, RollingHillsWithinTheFbmBound) {
    const pf::NoiseTerrainSettings settings = smallNoise(3);
    const pf::Heightfield terrain = pf::makeNoiseTerrain(settings);
    ASSERT_EQ(terrain.heights.size(), size_t(65 * 65));
    float amplitudeSum = 0;
    for (uint32_t octave = 0; octave < settings.octaves; ++octave)
        amplitudeSum += settings.amplitude * std::pow(settings.gain, float(octave));
    const auto [low, high] = std::minmax_element(terrain.heights.begin(), terrain.heights.end());
    EXPECT_LE(*high, amplitudeSum * std::sqrt(0.5f));
    EXPECT_GE(*low, -amplitudeSum * std::sqrt(0.5f));
    // Hills, not a plain: metres of relief over the 256 m square.
    EXPECT_GT(*high - *low, 0.25f * settings.amplitude);
    // Rolling, not rough: neighbouring samples 4 m apart differ by far less than the relief.
    float steepest = 0;
    for (uint32_t iz = 0; iz < terrain.resolution; ++iz)
        for (uint32_t ix = 0; ix + 1 < terrain.resolution; ++ix)
            steepest = std::max(steepest, std::abs(terrain.height(ix + 1, iz) - terrain.height(ix, iz)));
    EXPECT_LT(steepest, 0.2f * (*high - *low));
}

TEST(NoiseTerrain, RejectsAResolutionBelowTwo) {
    pf::NoiseTerrainSettings settings = smallNoise(0);
    settings.resolution = 1;
    EXPECT_THROW(pf::makeNoiseTerrain(settings), std::invalid_argument);
}

TEST(NoiseTerrain, AResolutionPastTheMemoryBudgetIsRefusedBeforeAllocating) {
    // A valid resolution (at most 8193) of 64 million samples, on a machine with 256 MiB to spare.
    pf::NoiseTerrainSettings settings = smallNoise(0);
    settings.resolution = 8000;
    settings.memory = {256ull << 20};
    EXPECT_EQ(pf::heightfieldBytes(8000), 8000ull * 8000 * 2 * sizeof(float));
    try {
        pf::makeNoiseTerrain(settings);
        FAIL() << "expected the terrain to be refused";
    } catch (const lsys::MemoryBudgetError& error) {
        EXPECT_STREQ(error.what(),
                     "memory budget: terrain needs 488.3 MiB, the limit is 256.0 MiB (set with --memory-budget)");
    }
    settings.resolution = 2000;
    EXPECT_EQ(pf::makeNoiseTerrain(settings).heights.size(), 2000u * 2000);
}

// 3×3 samples, 2 m apart: x and z in {-2, 0, 2}.
pf::Heightfield threeByThree() { return {3, 4.0f, {0, 1, 2, 3, 4, 5, 6, 7, 9}}; }

TEST(HeightAt, ReturnsTheSamplesAtGridPoints) {
    const pf::Heightfield terrain = threeByThree();
    for (uint32_t iz = 0; iz < 3; ++iz)
        for (uint32_t ix = 0; ix < 3; ++ix)
            EXPECT_FLOAT_EQ(pf::heightAt(terrain, terrain.coordinate(ix), terrain.coordinate(iz)),
                            terrain.height(ix, iz))
                << ix << "," << iz;
}

TEST(HeightAt, InterpolatesBilinearlyBetweenSamples) {
    const pf::Heightfield terrain = threeByThree();
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, -1.0f, -2.0f), 0.5f);                 // half way along the first row
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, -2.0f, -1.0f), 1.5f);                 // half way down the first column
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 1.0f, 1.0f), (4 + 5 + 7 + 9) / 4.0f); // centre of the last cell
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 1.5f, 0.5f),
                    4 * 0.25f * 0.75f + 5 * 0.75f * 0.75f + 7 * 0.25f * 0.25f + 9 * 0.75f * 0.25f);
}

TEST(HeightAt, ClampsOutsideTheSquare) {
    const pf::Heightfield terrain = threeByThree();
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, -50.0f, -50.0f), 0.0f);
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 50.0f, 50.0f), 9.0f);
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 50.0f, 0.0f), 5.0f);
}

TEST(Normals, OfAFlatPlaneAreUp) {
    const pf::Heightfield terrain = sampledTerrain(5, 8.0f, [](float, float) { return 3.0f; });
    EXPECT_EQ(pf::normalAt(terrain, 0.3f, -1.7f), glm::vec3(0, 1, 0));
    EXPECT_EQ(pf::slopeDegreesAt(terrain, 0.3f, -1.7f), 0.0f);
}

TEST(Normals, OfASlopeAreExactInsideAndAtTheEdges) {
    const float a = 0.5f, b = -0.25f;
    const pf::Heightfield terrain = sampledTerrain(9, 16.0f, [&](float x, float z) { return a * x + b * z + 1.0f; });
    const glm::vec3 expected = glm::normalize(glm::vec3(-a, 1, -b));
    const float expectedSlope = glm::degrees(std::atan(std::sqrt(a * a + b * b)));
    for (const glm::vec2 p : {glm::vec2(0.3f, 1.1f), glm::vec2(-8, -8), glm::vec2(8, 3), glm::vec2(7.9f, -8)}) {
        const glm::vec3 n = pf::normalAt(terrain, p.x, p.y);
        EXPECT_NEAR(glm::distance(n, expected), 0.0f, 1e-6f) << p.x << "," << p.y;
        EXPECT_NEAR(pf::slopeDegreesAt(terrain, p.x, p.y), expectedSlope, 1e-3f);
    }
}

class ImageTerrain : public ::testing::Test {
protected:
    void SetUp() override { std::filesystem::create_directories(PLANTFIELD_TEST_OUTPUT_DIR); }

    static std::string writeImage(const std::string& name, uint32_t width, uint32_t height,
                                  const std::vector<uint8_t>& rgb) {
        pf::RgbaImage image{width, height, {}};
        for (size_t i = 0; i < rgb.size(); i += 3)
            image.pixels.insert(image.pixels.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
        const std::string path = std::string(PLANTFIELD_TEST_OUTPUT_DIR) + "/" + name;
        pf::writePng(path, image);
        return path;
    }

    static std::string errorOf(const std::function<void()>& load) {
        try {
            load();
        } catch (const std::exception& e) {
            return e.what();
        }
        return "no error";
    }
};

TEST_F(ImageTerrain, MapsGreyLevelsToHeightsColumnToXRowToZ) {
    // Top row 0, 51; bottom row 204, 255.
    const std::string path = writeImage("grey_2x2.png", 2, 2, {0, 0, 0, 51, 51, 51, 204, 204, 204, 255, 255, 255});
    const pf::Heightfield terrain = pf::loadImageTerrain(path, 10.0f, 20.0f);
    ASSERT_EQ(terrain.resolution, 2u);
    EXPECT_FLOAT_EQ(terrain.size, 10.0f);
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, -5, -5), 0.0f);
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 5, -5), 4.0f);  // 51/255 · 20
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, -5, 5), 16.0f); // 204/255 · 20
    EXPECT_FLOAT_EQ(pf::heightAt(terrain, 5, 5), 20.0f);
}

TEST_F(ImageTerrain, AMissingFileIsAnErrorNamingIt) {
    const std::string path = std::string(PLANTFIELD_TEST_OUTPUT_DIR) + "/no_such_terrain.png";
    EXPECT_NE(errorOf([&] { pf::loadImageTerrain(path, 10, 1); }).find(path), std::string::npos);
}

TEST_F(ImageTerrain, AColoredPixelIsAnErrorNamingFileAndPixel) {
    const std::string path = writeImage("colour_2x2.png", 2, 2, {9, 9, 9, 9, 9, 9, 9, 9, 9, 10, 200, 30});
    const std::string error = errorOf([&] { pf::loadImageTerrain(path, 10, 1); });
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find("not greyscale: pixel (1, 1)"), std::string::npos) << error;
}

TEST_F(ImageTerrain, ANonSquareImageIsAnErrorNamingIt) {
    const std::string path = writeImage("wide_3x2.png", 3, 2, std::vector<uint8_t>(18, 100));
    const std::string error = errorOf([&] { pf::loadImageTerrain(path, 10, 1); });
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find("must be square, not 3x2"), std::string::npos) << error;
}

// The image's decoded pixels are checked against the budget from its
// header, before stb decodes it.
TEST_F(ImageTerrain, AnImagePastTheMemoryBudgetIsRefusedBeforeDecoding) {
    const std::string path = writeImage("grey_64.png", 64, 64, std::vector<uint8_t>(64 * 64 * 3, 100));
    const lsys::MemoryBudget small{16 * 1024}; // 64² pixels decode to 32 KiB, twice
    const std::string error = errorOf([&] { pf::loadImageTerrain(path, 10, 1, small); });
    EXPECT_NE(error.find("memory budget: image needs"), std::string::npos) << error;
    EXPECT_NE(error.find("the limit is 16.0 KiB"), std::string::npos) << error;
    EXPECT_EQ(pf::loadImageTerrain(path, 10, 1, lsys::MemoryBudget{1 << 20}).resolution, 64u);
}

TEST(TerrainMesh, CountsFollowTheResolution) {
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(pf::makeNoiseTerrain(smallNoise(1)));
    EXPECT_EQ(mesh.positions.size(), size_t(65 * 65));
    EXPECT_EQ(mesh.normals.size(), size_t(65 * 65));
    EXPECT_EQ(mesh.indices.size(), size_t(6 * 64 * 64));
}

TEST(TerrainMesh, VerticesSitOnTheSamplesAndTrianglesFaceUp) {
    const pf::Heightfield terrain = pf::makeNoiseTerrain(smallNoise(2));
    const pf::TerrainMesh mesh = pf::makeTerrainMesh(terrain);
    for (uint32_t iz = 0; iz < terrain.resolution; iz += 16)
        for (uint32_t ix = 0; ix < terrain.resolution; ix += 16) {
            const size_t v = size_t(iz) * terrain.resolution + ix;
            EXPECT_EQ(mesh.positions[v],
                      glm::vec3(terrain.coordinate(ix), terrain.height(ix, iz), terrain.coordinate(iz)));
            EXPECT_EQ(mesh.normals[v], pf::normalAt(terrain, mesh.positions[v].x, mesh.positions[v].z));
        }
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                        c = mesh.positions[mesh.indices[i + 2]];
        ASSERT_GT(glm::cross(b - a, c - a).y, 0.0f) << "triangle " << i / 3 << " faces down";
    }
    // Every vertex is used: no cell is missing.
    std::vector<bool> used(mesh.positions.size());
    for (uint32_t index : mesh.indices) used[index] = true;
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
}

} // namespace
