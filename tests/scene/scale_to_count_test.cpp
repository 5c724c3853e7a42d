#include "terrain_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {

using fieldtest::flatTerrain;

std::vector<pf::PlacementRule> forest() {
    pf::PlacementRule tree;
    tree.species = 0;
    tree.densityPerHectare = 100;
    tree.clearance = 2;
    pf::PlacementRule bush;
    bush.species = 1;
    bush.densityPerHectare = 900;
    return {tree, bush};
}

size_t countOf(const std::vector<pf::PlantInstance>& instances, uint32_t species) {
    return size_t(
        std::count_if(instances.begin(), instances.end(), [&](const auto& i) { return i.species == species; }));
}

TEST(ScaleToCount, FewerPlantsGiveASparserPoissonField) {
    const pf::Heightfield terrain = flatTerrain(200);
    const auto rules = forest();
    const auto full = pf::placeSpecies(terrain, rules, 1);
    ASSERT_GT(full.size(), 1000u);
    const size_t n = full.size() / 3;
    const auto sparse = pf::scaleToCount(terrain, rules, n, 1);
    ASSERT_EQ(sparse.size(), n);
    const double treeShare = double(countOf(full, 0)) / double(full.size());
    EXPECT_NEAR(double(countOf(sparse, 0)) / double(n), treeShare, 0.03);
    // Distances grew by about √3 and the field has no holes beyond twice the
    // grown bush distance (a random third of the full field would).
    const float grownBush = pf::ruleDistance(rules[1]) * std::sqrt(3.0f);
    std::vector<pf::PlantInstance> bushes;
    std::copy_if(sparse.begin(), sparse.end(), std::back_inserter(bushes),
                 [](const auto& i) { return i.species == 1; });
    EXPECT_GE(fieldtest::NearestPoints(fieldtest::groundPoints(bushes), 200, grownBush).minimumPairDistance(grownBush),
              0.9f * grownBush);
    EXPECT_LT(fieldtest::largestEmptyRadius(fieldtest::groundPoints(sparse), 200, 0, 0.5f, 3 * grownBush),
              2 * grownBush);
}

TEST(ScaleToCount, DensifiesToExactlyNWithEverySpecies) {
    const pf::Heightfield terrain = flatTerrain(100);
    const auto rules = forest();
    const size_t placed = pf::placeSpecies(terrain, rules, 2).size();
    const size_t n = placed * 3 + 17;
    const auto dense = pf::scaleToCount(terrain, rules, n, 2);
    ASSERT_EQ(dense.size(), n);
    EXPECT_GT(countOf(dense, 0), 0u);
    EXPECT_GT(countOf(dense, 1), countOf(dense, 0));
}

TEST(ScaleToCount, IsDeterministicAndHandlesZero) {
    const pf::Heightfield terrain = flatTerrain(100);
    const auto rules = forest();
    const auto a = pf::scaleToCount(terrain, rules, 1234, 3);
    const auto b = pf::scaleToCount(terrain, rules, 1234, 3);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i].position, b[i].position);
    EXPECT_TRUE(pf::scaleToCount(terrain, rules, 0, 3).empty());
}

TEST(ScaleToCount, FailsWhenTheRulesAdmitNoPlant) {
    pf::PlacementRule underwater;
    underwater.minDistance = 1;
    underwater.maxHeight = -1; // the flat terrain is at height 0
    EXPECT_THROW(pf::scaleToCount(flatTerrain(20), std::span(&underwater, 1), 10, 0), std::runtime_error);
}

} // namespace
