// LOD0 and the impostor of the same plant at the switch distance must look
// alike: same silhouette and colour, within stated differences.
#include "field_render.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pf::test {
namespace {

// A pixel belongs to the plant when it differs from the empty frame.
std::vector<bool> plantMask(const RgbaImage& image, const RgbaImage& empty) {
    std::vector<bool> mask(size_t(image.width) * image.height);
    for (size_t i = 0; i < mask.size(); ++i) {
        int delta = 0;
        for (int c = 0; c < 3; ++c)
            delta = std::max(delta, std::abs(image.pixels[i * 4 + c] - empty.pixels[i * 4 + c]));
        mask[i] = delta > 12;
    }
    return mask;
}

// The rows a mask covers: the top one, the bottom one and their mean.
struct MaskRows {
    double top = 1e30, bottom = -1e30, mean = 0.0;
};

MaskRows maskRows(const std::vector<bool>& mask, uint32_t width) {
    MaskRows rows;
    size_t count = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        const double y = double(i / width);
        rows.top = std::min(rows.top, y);
        rows.bottom = std::max(rows.bottom, y);
        rows.mean += y;
        ++count;
    }
    rows.mean /= double(std::max<size_t>(count, 1));
    return rows;
}

// The camera's elevation above the tree's centre, in degrees: from the
// horizon, from the impostor rings' elevations and half-way between them.
class LodTest : public GpuTest, public ::testing::WithParamInterface<float> {};

// test_lod.json: one 12 m broadleaf; the camera stands where the tree's
// bounding sphere spans the species' impostor threshold (260 px), looking at
// its centre from the elevation under test.
TEST_P(LodTest, ImpostorMatchesFullDetailAtTheSwitchDistance) {
    const float elevation = glm::radians(GetParam());
    const VkExtent2D size{480, 480};
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_lod.json");
    const PlantModelPool pool = buildPlantModels(scene);
    const gpu::PlantModel& model = pool.models[0].gpu;
    const float fov = 40.0f;
    const float pixelsPerMetre = float(size.height) / (2.0f * std::tan(glm::radians(fov) * 0.5f));
    const float distance = 2.0f * model.sphere.w * pixelsPerMetre / model.lod.y;

    Camera camera;
    camera.fovYDegrees = fov;
    camera.target = glm::vec3(model.sphere);
    camera.position = camera.target + glm::vec3(0.0f, std::sin(elevation), std::cos(elevation)) * distance;
    FieldShot shot{.scene = "test_lod.json", .size = size, .camera = camera, .shadows = SunShadows::none};
    shot.forcedLod = LOD_FULL;
    const FieldShotResult full = renderField(ctx, shot);
    shot.forcedLod = LOD_IMPOSTOR;
    const FieldShotResult impostor = renderField(ctx, shot);
    // Without forcing, this distance is the switch itself: the cull pass picks the impostor.
    shot.forcedLod.reset();
    const FieldShotResult chosen = renderField(ctx, shot);
    EXPECT_EQ(chosen.stats.plantsPerLod[LOD_IMPOSTOR] + chosen.stats.plantsPerLod[LOD_REDUCED], 1u);

    ASSERT_EQ(full.stats.plantsPerLod[LOD_FULL], 1u);
    ASSERT_EQ(impostor.stats.plantsPerLod[LOD_IMPOSTOR], 1u);
    // The same view of the same ground and sky without the tree (it stands behind the camera there).
    shot.scene = "test_lod_empty.json";
    const FieldShotResult empty = renderField(ctx, shot);
    ASSERT_EQ(empty.stats.plantsPerLod[0] + empty.stats.plantsPerLod[1] + empty.stats.plantsPerLod[2], 0u);
    const RgbaImage& background = empty.image;

    const std::vector<bool> a = plantMask(full.image, background), b = plantMask(impostor.image, background);
    size_t both = 0, either = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    ASSERT_GT(either, 5000u) << "the tree should cover a good part of the frame";
    const double overlap = double(both) / double(either);
    // Leaves differ pixel by pixel (a texel of the atlas covers several
    // screen pixels here), so colours are compared as 8×8 block averages,
    // what the eye sees at this distance, over blocks the plant touches.
    constexpr uint32_t kBlock = 8;
    double colorDelta = 0;
    size_t blocks = 0;
    for (uint32_t by = 0; by + kBlock <= size.height; by += kBlock)
        for (uint32_t bx = 0; bx + kBlock <= size.width; bx += kBlock) {
            double sum[2][3] = {};
            bool touched = false;
            for (uint32_t y = by; y < by + kBlock; ++y)
                for (uint32_t x = bx; x < bx + kBlock; ++x) {
                    const size_t i = size_t(y) * size.width + x;
                    touched = touched || a[i] || b[i];
                    for (int c = 0; c < 3; ++c) {
                        sum[0][c] += full.image.pixels[i * 4 + c];
                        sum[1][c] += impostor.image.pixels[i * 4 + c];
                    }
                }
            if (!touched) continue;
            for (int c = 0; c < 3; ++c) colorDelta += std::abs(sum[0][c] - sum[1][c]) / (kBlock * kBlock);
            ++blocks;
        }
    const double meanDelta = colorDelta / (3.0 * double(blocks));
    std::filesystem::create_directories(PLANTFIELD_TEST_OUTPUT_DIR);
    const std::string name = "/lod_" + std::to_string(int(GetParam())) + "deg_";
    writePng(std::string(PLANTFIELD_TEST_OUTPUT_DIR) + name + "full.png", full.image);
    writePng(std::string(PLANTFIELD_TEST_OUTPUT_DIR) + name + "impostor.png", impostor.image);
    // Where the silhouettes stand: a crown drawn lower or squashed moves its
    // top and mean rows, as a fraction of LOD0's height on screen.
    const MaskRows rowsFull = maskRows(a, size.width), rowsImpostor = maskRows(b, size.width);
    const double height = rowsFull.bottom - rowsFull.top + 1.0;
    const double topShift = (rowsImpostor.top - rowsFull.top) / height;
    const double meanShift = (rowsImpostor.mean - rowsFull.mean) / height;
    std::printf("LOD0 vs impostor at %.1f m, %.0f deg up: silhouette overlap %.3f, top %+.3f and mean row %+.3f of "
                "the height, mean 8x8 block colour difference %.1f/255\n",
                distance, GetParam(), overlap, topShift, meanShift, meanDelta);
    // Stated tolerances (docs/TESTING.md): from the horizon the silhouettes
    // overlap by at least 75 % (intersection over union; measured 0.82);
    // from above, where the rings' frames are up to 15° from the view, are
    // coarser (the frame holds the box's cylinder seen from above) and
    // orthographic against LOD0's perspective, by 62 % (measured 0.65 to
    // 0.69); the top and mean rows lie within 3.5 % and 4 % of the height
    // (measured at most 3.0 % and 3.4 %; a vertical card seen from 60° put
    // the top 21 % lower and overlapped 0.36, from 30° 4.1 % and 0.61);
    // block colours differ by at most 14/255 on average (measured 11 to 12:
    // the impostor crown is a little brighter).
    EXPECT_GE(overlap, GetParam() == 0.0f ? 0.75 : 0.62);
    EXPECT_LE(std::abs(topShift), 0.035);
    EXPECT_LE(std::abs(meanShift), 0.04);
    EXPECT_LE(meanDelta, 14.0);
}

INSTANTIATE_TEST_SUITE_P(Elevations, LodTest, ::testing::Values(0.0f, 15.0f, 30.0f, 45.0f, 60.0f),
                         [](const ::testing::TestParamInfo<float>& info) {
                             return std::to_string(int(info.param)) + "Degrees";
                         });

} // namespace
} // namespace pf::test
