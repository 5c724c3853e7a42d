// data/scenes/highlands.json, the L-system landscapes of the clouds-and-mountains chapter (§21–24) together: the
// massif's L-system peaks stand far above the noise valley where the forest grows, spruce climb its flanks, the clouds
// float above every summit, and the camera path stays above the ground and inside the terrain all the way.
#include "engine/scene/field_content.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

const Scene& highlands() {
    static const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/highlands.json");
    return scene;
}

const Heightfield& highlandsGround() {
    static const Heightfield ground = terrainOf(highlands());
    return ground;
}

float highestGround() {
    const Heightfield& ground = highlandsGround();
    return *std::max_element(ground.heights.begin(), ground.heights.end());
}

// The noise alone reaches its amplitude's few metres; the massif's peaks
// (data/terrain/massif.lsys at 20 m a unit) are what rise past 100 m.
TEST(HighlandsScene, TheMassifRisesFarAboveTheValley) {
    Scene noiseOnly = highlands();
    noiseOnly.terrain.lsystem.reset();
    const Heightfield plain = terrainOf(noiseOnly);
    EXPECT_LT(*std::max_element(plain.heights.begin(), plain.heights.end()), 20.0f);
    EXPECT_GT(highestGround(), 100.0f);
    EXPECT_LE(highestGround(), 200.0f) << "max_height's default bounds the summits";
    // The valley, where the camera starts, stays low.
    EXPECT_LT(heightAt(highlandsGround(), -60.0f, 150.0f), 20.0f);
}

TEST(HighlandsScene, CloudsFloatAboveEverySummit) {
    ASSERT_GE(highlands().clouds.size(), 3u);
    size_t casting = 0;
    for (const Cloud& cloud : highlands().clouds) {
        ASSERT_FALSE(cloud.spheres.empty());
        for (const CloudSphere& sphere : cloud.spheres)
            EXPECT_GT(sphere.centre.y - sphere.radius, highestGround()) << cloud.lsystem;
        casting += cloud.shadow;
    }
    EXPECT_GT(casting, 0u);
}

TEST(HighlandsScene, CameraPathStaysAboveTheGroundInsideTheTerrain) {
    const Scene& scene = highlands();
    ASSERT_GE(scene.camera.keyframes.size(), 2u);
    for (double t = scene.camera.keyframes.front().time; t <= scene.camera.keyframes.back().time; t += 0.1) {
        const glm::vec3 eye = cameraAt(scene.camera, t).position;
        EXPECT_LT(std::max(std::abs(eye.x), std::abs(eye.z)), 0.5f * scene.terrain.size) << "t = " << t;
        EXPECT_GT(eye.y - heightAt(highlandsGround(), eye.x, eye.z), 5.0f) << "t = " << t;
    }
}

} // namespace
} // namespace pf
