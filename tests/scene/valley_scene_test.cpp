// data/scenes/valley.json, the large landscape: a valid scene of 2 km × 2 km
// whose placement rules give about a million plants of several species, and
// whose camera path runs near the ground and above the canopy. Placing the
// million plants takes longer than a unit test should, so the count is the
// rules' expectation over the terrain (placement itself is tested at
// docs/FIELD.md's accuracy in placement_test.cpp).
#include "engine/scene/field_content.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {
namespace {

const std::string kValley = std::string(PLANTFIELD_DATA_DIR) + "/scenes/valley.json";

const Scene& valley() {
    static const Scene scene = loadScene(kValley);
    return scene;
}

const Heightfield& valleyGround() {
    static const Heightfield ground = terrainOf(valley());
    return ground;
}

bool admits(const PlacementRule& rule, const Heightfield& ground, float x, float z) {
    const float h = heightAt(ground, x, z);
    return h >= rule.minHeight && h <= rule.maxHeight && slopeDegreesAt(ground, x, z) <= rule.maxSlopeDegrees;
}

// Plants the rules should place: each rule's density over the ground it
// admits (height, slope), less the discs its clearance keeps free around the
// plants of the rules sampled before it (larger distances first). A rule's
// own Poisson-disk points sit right at a disc's rim, so a disc costs it only
// the part more than half its own distance from the rim; and the discs of one
// earlier rule are farther apart than their diameter, so their areas add.
// Within 3 % of what placeSpecies gives for this scene (994 953 plants) and
// the default one.
double expectedPlants(const std::vector<PlacementRule>& rules, const Heightfield& ground) {
    std::vector<size_t> order(rules.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return ruleDistance(rules[a]) > ruleDistance(rules[b]); });
    constexpr float kStep = 4.0f;
    const float half = 0.5f * ground.size;
    double plants = 0.0;
    std::vector<double> perSquareMetre(rules.size());
    for (float z = -half + 0.5f * kStep; z < half; z += kStep)
        for (float x = -half + 0.5f * kStep; x < half; x += kStep) {
            for (size_t k = 0; k < order.size(); ++k) {
                const PlacementRule& rule = rules[order[k]];
                double kept = 1.0;
                for (size_t e = 0; e < k; ++e) {
                    const double clearance = std::max(rules[order[e]].clearance, rule.clearance);
                    const double costs = std::max(0.0, clearance - 0.5 * ruleDistance(rule));
                    kept -= perSquareMetre[e] * std::numbers::pi * costs * costs;
                }
                perSquareMetre[k] =
                    admits(rule, ground, x, z) ? rule.densityPerHectare / 10000.0 * std::max(kept, 0.0) : 0.0;
                plants += perSquareMetre[k] * kStep * kStep;
            }
        }
    return plants;
}

TEST(ValleyScene, IsTwoKilometresSquareWithSeveralSpeciesAtNaturalDensities) {
    const Scene& scene = valley();
    EXPECT_EQ(scene.terrain.size, 2000.0f);
    EXPECT_TRUE(std::holds_alternative<NoiseHeightfield>(scene.terrain.heightfield)) << "a noise terrain can grow";
    EXPECT_GE(scene.species.size(), 5u);
    for (const Species& species : scene.species) {
        EXPECT_EQ(species.placement.mode, PlacementMode::Density) << species.name;
        EXPECT_LE(species.placement.densityPerHectare, 10000.0f) << species.name << ": denser than one a square metre";
    }
}

TEST(ValleyScene, PlacementRulesExpectAboutAMillionPlants) {
    const double expected = expectedPlants(placementRules(valley()), valleyGround());
    EXPECT_NEAR(expected, 1.0e6, 1.0e5);
}

TEST(ValleyScene, CameraPathRunsNearTheGroundAndAboveTheCanopy) {
    const Scene& scene = valley();
    float tallest = 0.0f;
    for (const Species& species : scene.species) tallest = std::max(tallest, species.height.value_or(0.0f));
    ASSERT_GE(scene.camera.keyframes.size(), 2u);
    const double first = scene.camera.keyframes.front().time, last = scene.camera.keyframes.back().time;
    float lowest = 1e9f, highest = -1e9f;
    for (double t = first; t <= last; t += 0.1) {
        const glm::vec3 eye = cameraAt(scene.camera, t).position;
        EXPECT_LT(std::max(std::abs(eye.x), std::abs(eye.z)), 0.5f * scene.terrain.size) << "t = " << t;
        const float above = eye.y - heightAt(valleyGround(), eye.x, eye.z);
        EXPECT_GT(above, 0.5f) << "below the ground at t = " << t;
        lowest = std::min(lowest, above);
        highest = std::max(highest, above);
    }
    EXPECT_LT(lowest, 3.0f) << "never near the ground";
    EXPECT_GT(highest, tallest + 10.0f) << "never above the canopy";
}

} // namespace
} // namespace pf
