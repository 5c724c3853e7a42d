// The late cull's occlusion test (shaders/shared/occlusion_test.h) on the CPU, on
// synthetic depth buffers: a wall at a known distance, hidden and visible
// spheres, a wall with a gap, spheres at the near plane, and the properties
// it rests on (the screen rectangle holds every point of the sphere, the
// level chosen holds the rectangle in 2×2 texels).
#include "engine/field/cull_reference.h"
#include "engine/field/cull_uniforms.h"
#include "engine/image/depth_pyramid_levels.h"
#include "engine/scene/camera.h"
#include "shaders/shared/occlusion_test.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pf {
namespace {

constexpr PixelExtent kViewport{160, 90};

// A camera at the origin looking down −z; depth of a wall `distance` ahead
// over the pixel columns [fromX, toX) (the rest: nothing drawn, far plane).
struct WallScene {
    Camera camera;
    gpu::CullUniforms uniforms{};
    std::vector<float> depth = std::vector<float>(size_t(kViewport.width) * kViewport.height, 1.0f);

    WallScene() {
        camera.position = {0.0f, 0.0f, 0.0f};
        camera.target = {0.0f, 0.0f, -1.0f};
        camera.fovYDegrees = 60.0f;
        camera.nearPlane = 0.1f;
        camera.farPlane = 1000.0f;
        const glm::uvec2 viewport(kViewport.width, kViewport.height);
        setOcclusionUniforms(uniforms, viewMatrix(camera), projectionMatrix(camera, viewport), viewport,
                             camera.nearPlane, uint32_t(depthPyramidExtents(kViewport).size()));
    }
    float depthAt(float distance) const {
        const glm::vec4 clip =
            projectionMatrix(camera, {kViewport.width, kViewport.height}) * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
        return clip.z / clip.w;
    }
    void wall(float distance, uint32_t fromX = 0, uint32_t toX = kViewport.width) {
        for (uint32_t y = 0; y < kViewport.height; ++y)
            for (uint32_t x = fromX; x < toX; ++x) depth[size_t(y) * kViewport.width + x] = depthAt(distance);
    }
    bool occluded(glm::vec3 centre, float radius) const {
        return sphereOccludedOnCpu(glm::vec4(centre, radius), uniforms, depthPyramidOnCpu(depth, kViewport));
    }
};

TEST(OcclusionTest, NothingDrawnHidesNothing) {
    const WallScene s;
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -50.0f}, 1.0f));
    EXPECT_FALSE(s.occluded({5.0f, 2.0f, -500.0f}, 0.5f));
}

TEST(OcclusionTest, SpheresBehindAWallAreHiddenAndBeforeItAreNot) {
    WallScene s;
    s.wall(10.0f);
    EXPECT_TRUE(s.occluded({0.0f, 0.0f, -20.0f}, 1.0f));
    EXPECT_TRUE(s.occluded({3.0f, -2.0f, -40.0f}, 5.0f));
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -5.0f}, 1.0f)) << "in front of the wall";
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -10.5f}, 1.0f)) << "its nearest point pokes through the wall";
    EXPECT_TRUE(s.occluded({0.0f, 0.0f, -11.5f}, 1.0f)) << "wholly behind it";
}

TEST(OcclusionTest, ASphereSeenThroughAGapIsVisible) {
    WallScene s;
    // Columns 80 to 89 open: the wall covers the rest.
    s.wall(10.0f, 0, 80);
    s.wall(10.0f, 90, kViewport.width);
    // Straight ahead (the centre column is 80): seen through the gap.
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -30.0f}, 0.5f));
    // Far to the left, behind the wall.
    EXPECT_TRUE(s.occluded({-10.0f, 0.0f, -30.0f}, 0.5f));
    // Large enough that its rectangle reaches the gap.
    EXPECT_FALSE(s.occluded({-3.0f, 0.0f, -30.0f}, 3.5f));
}

TEST(OcclusionTest, SpheresAtTheNearPlaneAreNeverHidden) {
    WallScene s;
    s.wall(0.15f);
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -1.0f}, 1.0f)) << "reaches behind the camera";
    EXPECT_FALSE(s.occluded({0.0f, 0.0f, -0.5f}, 0.45f)) << "within the near plane";
    EXPECT_TRUE(s.occluded({0.0f, 0.0f, -3.0f}, 1.0f));
}

// Points on the sphere's surface project inside its rectangle, and the
// sphere's nearest depth is no farther than any of theirs.
TEST(OcclusionTest, ScreenRectangleAndDepthBoundTheSphere) {
    const WallScene s;
    const glm::mat4 proj = projectionMatrix(s.camera, {kViewport.width, kViewport.height});
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 500; ++i) {
        const glm::vec4 viewSphere(unit(rng) * 20.0f, unit(rng) * 10.0f, -30.0f + unit(rng) * 25.0f,
                                   1.0f + 3.0f * std::abs(unit(rng)));
        if (gpu::sphereNearCamera(viewSphere, s.camera.nearPlane)) continue;
        const glm::vec4 rect = gpu::sphereScreenRect(viewSphere, s.uniforms.projection);
        const float nearest = gpu::sphereNearestDepth(viewSphere, s.uniforms.projection);
        for (int k = 0; k < 64; ++k) {
            const glm::vec3 dir = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
            const glm::vec4 clip = proj * glm::vec4(glm::vec3(viewSphere) + dir * viewSphere.w, 1.0f);
            const glm::vec2 uv(clip.x / clip.w * 0.5f + 0.5f, 0.5f - clip.y / clip.w * 0.5f);
            EXPECT_GE(uv.x, rect.x - 1e-5f);
            EXPECT_LE(uv.x, rect.z + 1e-5f);
            EXPECT_GE(uv.y, rect.y - 1e-5f);
            EXPECT_LE(uv.y, rect.w + 1e-5f);
            EXPECT_LE(nearest, clip.z / clip.w + 1e-6f);
        }
    }
}

// The level chosen holds any pixel rectangle in at most 2×2 of its texels,
// and the level below (when there is one) would not.
TEST(OcclusionTest, LevelHoldsTheRectangleInTwoByTwoTexels) {
    const uint32_t levels = uint32_t(depthPyramidExtents(kViewport).size());
    std::mt19937 rng(3);
    std::uniform_int_distribution<uint32_t> x(0, kViewport.width - 1), y(0, kViewport.height - 1);
    for (int i = 0; i < 2000; ++i) {
        uint32_t x0 = x(rng), x1 = x(rng), y0 = y(rng), y1 = y(rng);
        const glm::uvec4 pixels(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1));
        const uint32_t level = gpu::pyramidLevel(pixels, levels);
        ASSERT_LT(level, levels);
        const glm::uvec4 t = pixels >> (level + 1u);
        EXPECT_LE(t.z - t.x, 1u);
        EXPECT_LE(t.w - t.y, 1u);
        if (level > 0) {
            const glm::uvec4 finer = pixels >> level;
            EXPECT_TRUE(finer.z - finer.x > 1u || finer.w - finer.y > 1u);
        }
    }
}

} // namespace
} // namespace pf
