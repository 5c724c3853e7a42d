#include "terrain_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace {

using fieldtest::flatTerrain;
using fieldtest::groundPoints;
using fieldtest::largestEmptyRadius;
using fieldtest::NearestPoints;
using fieldtest::sampledTerrain;

// The task asks for holes below 2 r; Bridson's sampling with 30 candidates
// leaves about 1.2 r (docs/FIELD.md), so this bound also catches a front that
// stalls at the border of a restricted region.
constexpr float kLargestHole = 1.4f;

pf::PlacementRule ruleWithDistance(float distance, uint32_t species = 0) {
    pf::PlacementRule rule;
    rule.species = species;
    rule.minDistance = distance;
    return rule;
}

bool sameInstances(const std::vector<pf::PlantInstance>& a, const std::vector<pf::PlantInstance>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const auto& x, const auto& y) {
               return x.position == y.position && x.rotation == y.rotation && x.scale == y.scale &&
                      x.species == y.species && x.variant == y.variant && x.windPhase == y.windPhase;
           });
}

TEST(PoissonDisk, EveryPairIsAtLeastTheDistanceApart) {
    const float r = 2.0f;
    const auto instances = pf::placePoissonDisk(flatTerrain(120), ruleWithDistance(r), 1);
    ASSERT_GT(instances.size(), 1000u);
    EXPECT_GE(NearestPoints(groundPoints(instances), 120, r).minimumPairDistance(r), r);
}

TEST(PoissonDisk, LeavesNoHoleOfRadiusTwiceTheDistance) {
    const float r = 2.0f;
    const auto points = groundPoints(pf::placePoissonDisk(flatTerrain(100), ruleWithDistance(r), 2));
    // Bridson's sampling is nearly maximal: holes stay near 1.2 r, far below 2 r.
    EXPECT_LT(largestEmptyRadius(points, 100, 0, 0.25f, 3 * r), kLargestHole * r);
}

TEST(PoissonDisk, StaysInsideTheTerrainSquare) {
    for (const pf::PlantInstance& instance : pf::placePoissonDisk(flatTerrain(50), ruleWithDistance(1.5f), 3)) {
        ASSERT_LE(std::abs(instance.position.x), 25.0f);
        ASSERT_LE(std::abs(instance.position.z), 25.0f);
    }
}

TEST(PoissonDisk, SameSeedSameFieldDifferentSeedDifferentField) {
    const pf::Heightfield terrain = flatTerrain(60);
    pf::PlacementRule rule = ruleWithDistance(2);
    rule.minScale = 0.5f;
    rule.maxScale = 2;
    rule.variants = 4;
    const auto first = pf::placePoissonDisk(terrain, rule, 11);
    EXPECT_TRUE(sameInstances(first, pf::placePoissonDisk(terrain, rule, 11)));
    const auto other = pf::placePoissonDisk(terrain, rule, 12);
    EXPECT_FALSE(sameInstances(first, other));
    EXPECT_NE(first.front().position, other.front().position);
}

TEST(PoissonDisk, CountMatchesTheDensity) {
    // 400 m square = 16 ha; edges are a small fraction of it.
    for (const float density : {50.0f, 400.0f}) {
        pf::PlacementRule rule;
        rule.densityPerHectare = density;
        const size_t count = pf::placePoissonDisk(flatTerrain(400), rule, 5).size();
        EXPECT_NEAR(double(count), density * 16.0, density * 16.0 * 0.04) << density << " plants per hectare";
    }
}

TEST(PoissonDisk, DensityIsKeptInsideARestrictedRegion) {
    // A ramp rising 1 m per 10 m: heights from -20 to 20; the band [-10, 10] is half the square.
    const pf::Heightfield terrain = sampledTerrain(3, 400, [](float x, float) { return 0.1f * x; });
    pf::PlacementRule rule;
    rule.densityPerHectare = 200;
    rule.minHeight = -10;
    rule.maxHeight = 10;
    const auto instances = pf::placePoissonDisk(terrain, rule, 6);
    for (const pf::PlantInstance& instance : instances) {
        ASSERT_GE(instance.position.y, -10.0f);
        ASSERT_LE(instance.position.y, 10.0f);
    }
    EXPECT_NEAR(double(instances.size()), 200.0 * 8, 200.0 * 8 * 0.05);
    // Plants reach the border of the band as closely as anywhere else: ghost
    // samples outside it never block them (if they did, holes of 1.5–1.8 r
    // would open along the border).
    const float r = pf::ruleDistance(rule);
    EXPECT_LT(largestEmptyRadius(groundPoints(instances), 400, 0, 0.5f, 3 * r,
                                 [](glm::vec2 p) { return std::abs(p.x) <= 100; }),
              kLargestHole * r);
}

TEST(PoissonDisk, RespectsTheSlopeLimit) {
    // Flat for x < 0, then a 1:1 slope (45°) for x > 0.
    const pf::Heightfield terrain = sampledTerrain(101, 100, [](float x, float) { return std::max(x, 0.0f); });
    pf::PlacementRule rule = ruleWithDistance(1.5f);
    rule.maxSlopeDegrees = 30;
    const auto instances = pf::placePoissonDisk(terrain, rule, 7);
    ASSERT_GT(instances.size(), 500u);
    for (const pf::PlantInstance& instance : instances)
        ASSERT_LE(pf::slopeDegreesAt(terrain, instance.position.x, instance.position.z), 30.0f);
    // The flat half is filled.
    const float r = pf::ruleDistance(rule);
    EXPECT_LT(largestEmptyRadius(groundPoints(instances), 100, 0, 0.25f, 3 * r, [](glm::vec2 p) { return p.x <= 0; }),
              kLargestHole * r);
}

TEST(PoissonDisk, InstancesStandOnTheTerrainWithAttributesInRange) {
    const pf::Heightfield terrain = pf::makeNoiseTerrain({.resolution = 33, .size = 100, .seed = 4});
    pf::PlacementRule rule = ruleWithDistance(1.5f, 3);
    rule.minScale = 0.8f;
    rule.maxScale = 1.3f;
    rule.variants = 5;
    const auto instances = pf::placePoissonDisk(terrain, rule, 8);
    std::vector<size_t> perVariant(rule.variants);
    const float tau = 2 * std::numbers::pi_v<float>;
    for (const pf::PlantInstance& instance : instances) {
        ASSERT_EQ(instance.position.y, pf::heightAt(terrain, instance.position.x, instance.position.z));
        ASSERT_EQ(instance.species, 3u);
        ASSERT_GE(instance.scale, 0.8f);
        ASSERT_LE(instance.scale, 1.3f);
        ASSERT_GE(instance.rotation, 0.0f);
        ASSERT_LT(instance.rotation, tau);
        ASSERT_GE(instance.windPhase, 0.0f);
        ASSERT_LT(instance.windPhase, tau);
        ASSERT_LT(instance.variant, 5u);
        ++perVariant[instance.variant];
    }
    // Attributes are spread, not constant: each variant has about a fifth.
    for (size_t count : perVariant) EXPECT_NEAR(double(count), instances.size() / 5.0, instances.size() * 0.05);
}

TEST(PoissonDisk, RejectsInvalidRules) {
    const pf::Heightfield terrain = flatTerrain(10);
    EXPECT_THROW(pf::placePoissonDisk(terrain, ruleWithDistance(0), 0), std::invalid_argument);
    pf::PlacementRule noVariants = ruleWithDistance(1);
    noVariants.variants = 0;
    EXPECT_THROW(pf::placePoissonDisk(terrain, noVariants, 0), std::invalid_argument);
    pf::PlacementRule scales = ruleWithDistance(1);
    scales.minScale = 2;
    EXPECT_THROW(pf::placePoissonDisk(terrain, scales, 0), std::invalid_argument);
    EXPECT_THROW(pf::placePoissonDisk(flatTerrain(1e6f), ruleWithDistance(0.01f), 0), std::invalid_argument);
}

std::vector<glm::vec2> pointsOf(const std::vector<pf::PlantInstance>& instances, uint32_t species) {
    std::vector<pf::PlantInstance> selected;
    std::copy_if(instances.begin(), instances.end(), std::back_inserter(selected),
                 [&](const auto& i) { return i.species == species; });
    return groundPoints(selected);
}

// Smallest distance from a point of `a` to a point of `b`.
float separation(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b, float size, float within) {
    const NearestPoints nearest(b, size, within);
    float smallest = std::numeric_limits<float>::infinity();
    for (glm::vec2 p : a) smallest = std::min(smallest, nearest.nearest(p, within));
    return smallest;
}

TEST(PlaceSpecies, SpeciesKeepTheLargerClearanceAndTheirOwnDistance) {
    pf::PlacementRule grass = ruleWithDistance(0.7f, 2);
    pf::PlacementRule tree = ruleWithDistance(8, 0);
    tree.clearance = 3;
    pf::PlacementRule bush = ruleWithDistance(2.5f, 1);
    bush.clearance = 1.2f;
    const std::vector<pf::PlacementRule> rules = {grass, tree, bush}; // sampled tree, bush, grass
    const auto instances = pf::placeSpecies(flatTerrain(80), rules, 9);
    const auto trees = pointsOf(instances, 0), bushes = pointsOf(instances, 1), grasses = pointsOf(instances, 2);
    ASSERT_GT(trees.size(), 50u);
    ASSERT_GT(bushes.size(), 300u);
    ASSERT_GT(grasses.size(), 3000u);
    EXPECT_GE(separation(bushes, trees, 80, 10), 3.0f);
    EXPECT_GE(separation(grasses, trees, 80, 10), 3.0f);
    EXPECT_GE(separation(grasses, bushes, 80, 10), 1.2f);
    EXPECT_GE(NearestPoints(trees, 80, 8).minimumPairDistance(8), 8.0f);
    EXPECT_GE(NearestPoints(bushes, 80, 2.5f).minimumPairDistance(2.5f), 2.5f);
    EXPECT_GE(NearestPoints(grasses, 80, 0.7f).minimumPairDistance(0.7f), 0.7f);
    // Output is grouped by rule in the order given.
    EXPECT_EQ(instances.front().species, 2u);
    EXPECT_EQ(instances.back().species, 1u);
}

TEST(PlaceSpecies, AnotherRuleOnlyRemovesPlantsItsClearanceCovers) {
    // Bushes sampled alone and with trees of zero clearance are the same field.
    const pf::Heightfield terrain = flatTerrain(60);
    const pf::PlacementRule bush = ruleWithDistance(2, 1);
    const std::vector<pf::PlacementRule> rules = {bush, ruleWithDistance(6, 0)};
    const auto both = pf::placeSpecies(terrain, rules, 10);
    const auto alone = pf::placeSpecies(terrain, std::span(rules).first(1), 10);
    EXPECT_TRUE(sameInstances(alone, std::vector(both.begin(), both.begin() + ptrdiff_t(alone.size()))));
}

} // namespace
