// The switch from plants to a cluster's canopy must not show: at the
// distance where a leaf of the quadtree turns far, the leaf drawn as its
// canopy and as its plants (impostors, the small ones hidden, as the cull
// pass picks them) look alike over the leaf's screen rectangle. Both frames
// are written to the test output folder.
#include "field_render.h"
#include "gpu_test.h"

#include "shaders/shared/cluster_select.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pf::test {
namespace {

// The bars the canopy meets at the switch (docs/CLUSTERS.md, measured
// 19.9 dB and 3 levels at the default threshold of one pixel a cell): the
// canopy keeps the leaf's colour and outline, not its single trees.
constexpr double kMinPsnr = 18.0;
constexpr double kMaxMeanDelta = 8.0; // of 255

// The pixels of `image` inside [lo, hi).
RgbaImage crop(const RgbaImage& image, glm::ivec2 lo, glm::ivec2 hi) {
    RgbaImage out;
    out.width = uint32_t(hi.x - lo.x);
    out.height = uint32_t(hi.y - lo.y);
    for (int y = lo.y; y < hi.y; ++y)
        for (int x = lo.x; x < hi.x; ++x)
            for (int c = 0; c < 4; ++c) out.pixels.push_back(image.pixels[(size_t(y) * image.width + x) * 4 + c]);
    return out;
}

class ClusterLodTest : public GpuTest {};

// The leaf's screen rectangle drawn far (its canopy) and near (its plants).
struct SwitchShots {
    RgbaImage far, near;
    float distance = 0.0f;
};

// The leaf with the most plants on the field's -z edge, seen from outside
// the field, 25° above the horizon, where one canopy cell covers just under
// the threshold in pixels: every leaf drawn far, then every leaf near.
SwitchShots switchShots(const GpuContext& ctx, const std::string& scene) {
    const VkExtent2D size{640, 360};
    FieldSequence sequence(ctx, scene, size);
    const FieldRenderer& renderer = sequence.renderer();
    const ClusterTree& tree = renderer.clusterTree();
    const float threshold = renderer.settings().clusters.thresholdPixels;
    EXPECT_GT(tree.leafCount(), 0u);
    uint32_t leaf = 0;
    float edge = 1e30f;
    for (uint32_t l = 0; l < tree.leafCount(); ++l) edge = std::min(edge, tree.nodes[l].square.y);
    for (uint32_t l = 0; l < tree.leafCount(); ++l)
        if (tree.nodes[l].square.y == edge && tree.nodes[l].range.y > tree.nodes[leaf].range.y) leaf = l;
    const gpu::ClusterNode& node = tree.nodes[leaf];

    Camera camera;
    camera.fovYDegrees = 50.0f;
    camera.farPlane = 3000.0f;
    camera.target = 0.5f * glm::vec3(node.boxMin + node.boxMax);
    const glm::vec3 away =
        glm::normalize(glm::vec3(0.0f, std::sin(glm::radians(25.0f)), -std::cos(glm::radians(25.0f))));
    const float pixelsPerMetre = float(size.height) / (2.0f * std::tan(glm::radians(camera.fovYDegrees) * 0.5f));
    float lo = 0.0f, hi = 10000.0f;
    for (int i = 0; i < 60; ++i) {
        const float mid = 0.5f * (lo + hi);
        const float pixels = gpu::clusterCellPixels(node, glm::vec4(camera.target + away * mid, pixelsPerMetre));
        (pixels > 0.98f * threshold ? lo : hi) = mid;
    }
    camera.position = camera.target + away * hi;

    FieldView view;
    view.camera = camera;
    view.forcedCut = CLUSTER_CUT_ALL_FAR;
    const FieldShotResult far = sequence.frame(view);
    view.forcedCut = CLUSTER_CUT_ALL_NEAR;
    const FieldShotResult near = sequence.frame(view);
    view.forcedCut.reset();
    const FieldShotResult chosen = sequence.frame(view);
    EXPECT_EQ(far.stats.nearPlants, 0u);
    EXPECT_GT(far.stats.clustersFar, 0u);
    EXPECT_EQ(near.stats.clustersFar, 0u);
    EXPECT_GT(near.stats.plantsPerLod[LOD_IMPOSTOR], 0u);
    EXPECT_GT(chosen.stats.clustersFar, 0u) << "at this distance the leaf is drawn far";

    const glm::mat4 viewProj =
        glm::perspectiveRH_ZO(glm::radians(camera.fovYDegrees), float(size.width) / float(size.height),
                              camera.nearPlane, camera.farPlane) *
        glm::lookAtRH(camera.position, camera.target, glm::vec3(0, 1, 0));
    glm::vec2 rectLo(1e30f), rectHi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? node.boxMax.x : node.boxMin.x, (corner & 2) ? node.boxMax.y : node.boxMin.y,
                          (corner & 4) ? node.boxMax.z : node.boxMin.z);
        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
        const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size.width, size.height);
        rectLo = glm::min(rectLo, pixel);
        rectHi = glm::max(rectHi, pixel);
    }
    const glm::ivec2 extent(size.width, size.height);
    const glm::ivec2 lower = glm::clamp(glm::ivec2(glm::floor(rectLo)), glm::ivec2(0), extent);
    const glm::ivec2 upper = glm::clamp(glm::ivec2(glm::ceil(rectHi)), glm::ivec2(0), extent);
    EXPECT_GT((upper.x - lower.x) * (upper.y - lower.y), 50) << "the leaf covers some pixels";
    const std::string dir = PLANTFIELD_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    const std::string name = std::filesystem::path(scene).stem().string();
    writePng(dir + "/cluster_switch_" + name + "-far.png", far.image);
    writePng(dir + "/cluster_switch_" + name + "-near.png", near.image);
    return {crop(far.image, lower, upper), crop(near.image, lower, upper), hi};
}

glm::dvec3 meanColor(const RgbaImage& image) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < image.pixels.size(); i += 4)
        sum += glm::dvec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
    return sum / double(image.pixels.size() / 4);
}

// default.json, the built-in forest with its fog: PSNR over the leaf's rectangle.
TEST_F(ClusterLodTest, CanopyMatchesThePlantsAtTheSwitchDistance) {
    const SwitchShots shots = switchShots(ctx, "default.json");
    const ImageDiff diff = compareImages(shots.far, shots.near, 0);
    std::printf("default.json: leaf at %.0f m, %ux%u px, PSNR %.2f dB\n", shots.distance, shots.far.width,
                shots.far.height, diff.psnr);
    EXPECT_GE(diff.psnr, kMinPsnr);
}

// test_clusters.json, the same forest under the valley's thinner fog: the
// canopy cannot draw single trees a few pixels high, but it has their
// colour: the leaf's mean colour stays within kMaxMeanDelta per channel.
TEST_F(ClusterLodTest, CanopyHasThePlantsMeanColorUnderThinFog) {
    const SwitchShots shots = switchShots(ctx, "test_clusters.json");
    const glm::dvec3 far = meanColor(shots.far), near = meanColor(shots.near);
    std::printf("test_clusters.json: leaf at %.0f m, PSNR %.2f dB, mean far (%.1f %.1f %.1f) near (%.1f %.1f %.1f)\n",
                shots.distance, compareImages(shots.far, shots.near, 0).psnr, far.r, far.g, far.b, near.r, near.g,
                near.b);
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(far[c] - near[c]), kMaxMeanDelta) << "channel " << c;
}

} // namespace
} // namespace pf::test
