// The clouds' shadow map (engine/scene/cloud_shadow.h): the sunlight let
// through under a sphere is the cloud shader's opacity, compounded, and
// the map follows the sun's slant.
#include "engine/scene/cloud_shadow.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf {
namespace {

Cloud castingCloud(std::vector<CloudSphere> spheres, bool shadow = true) {
    Cloud cloud;
    cloud.spheres = std::move(spheres);
    cloud.shadow = shadow;
    return cloud;
}

float transmittanceAt(const CloudShadowMap& map, glm::vec2 point) {
    const glm::ivec2 texel = glm::ivec2(glm::round((point - map.origin) / map.texel));
    return map.transmittance[size_t(texel.y) * map.width + texel.x];
}

// The sun overhead: under the centre the ray crosses two radii
// (e^(−2.4)), two spheres stacked give the square, the map's border lets
// all the light through.
TEST(CloudShadow, UnderASphereTheLightIsItsTransmittanceCompounded) {
    const glm::vec3 overhead(0.0f, 1.0f, 0.0f);
    const CloudShadowMap one = bakeCloudShadows({castingCloud({{{10, 100, 20}, 8, 0.0f}})}, overhead, 1.0f);
    ASSERT_GT(one.width, 16u);
    EXPECT_NEAR(transmittanceAt(one, {10, 20}), std::exp(-2.4f), 1e-5f);
    EXPECT_EQ(one.transmittance.front(), 1.0f);
    EXPECT_EQ(one.transmittance.back(), 1.0f);
    const CloudShadowMap two =
        bakeCloudShadows({castingCloud({{{10, 100, 20}, 8, 0.0f}, {{10, 130, 20}, 8, 1.0f}})}, overhead, 1.0f);
    EXPECT_NEAR(transmittanceAt(two, {10, 20}), std::exp(-4.8f), 1e-5f);
}

// A slanting sun moves the shadow away from it: the ray from the plane
// point under the sphere's centre, cloudShadowPlanePoint, hits the centre.
TEST(CloudShadow, TheShadowFallsAwayFromTheSun) {
    const glm::vec3 sun = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)); // 45° up, toward +x
    const glm::vec3 centre(0.0f, 50.0f, 0.0f);
    EXPECT_NEAR(cloudShadowPlanePoint(centre, sun).x, -50.0f, 1e-4f);
    const CloudShadowMap map = bakeCloudShadows({castingCloud({{centre, 5, 0.0f}})}, sun, 0.5f);
    EXPECT_NEAR(transmittanceAt(map, {-50, 0}), std::exp(-2.4f), 1e-4f);
    EXPECT_EQ(transmittanceAt(map, {-50 + 9, 0}), 1.0f) << "the shadow reaches 5·√2 m from its middle along the sun";
}

TEST(CloudShadow, OnlyCloudsAskedForCastAndNotUnderALowSun) {
    const std::vector<Cloud> quiet = {castingCloud({{{0, 100, 0}, 8, 0.0f}}, false)};
    EXPECT_EQ(bakeCloudShadows(quiet, {0, 1, 0}).width, 0u);
    const std::vector<Cloud> casting = {castingCloud({{{0, 100, 0}, 8, 0.0f}})};
    EXPECT_EQ(bakeCloudShadows(casting, glm::normalize(glm::vec3(1.0f, 0.02f, 0.0f))).width, 0u);
    EXPECT_GT(bakeCloudShadows(casting, glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f))).width, 0u);
}

} // namespace
} // namespace pf
