// The clouds of data/clouds (the clouds-and-mountains chapter, §23–24) as the spheres their
// L-systems draw (engine/scene/cloud_spheres.h), and the frame's billboards
// made from them (engine/scene/cloud_billboards.h).
#include "engine/scene/cloud_billboards.h"
#include "engine/scene/cloud_spheres.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pf {
namespace {

std::filesystem::path cloudFile(const std::string& name) {
    return std::filesystem::path(PLANTFIELD_DATA_DIR) / "clouds" / name;
}

struct CloudBox {
    glm::vec3 low{1e30f}, high{-1e30f};
};

CloudBox boxOf(const std::vector<CloudSphere>& spheres) {
    CloudBox box;
    for (const CloudSphere& s : spheres) {
        box.low = glm::min(box.low, s.centre - s.radius);
        box.high = glm::max(box.high, s.centre + s.radius);
    }
    return box;
}

struct LayoutCase {
    const char* file;
    size_t spheres;
};

class CloudLayoutTest : public testing::TestWithParam<LayoutCase> {};

// Each layout draws its pinned number of spheres, twice the same, scaled to
// its size with the middle of its bottom at the position.
TEST_P(CloudLayoutTest, SpheresArePinnedDeterministicAndPlaced) {
    const glm::vec3 base(10.0f, 300.0f, -40.0f);
    const std::vector<CloudSphere> spheres = cloudSpheres(cloudFile(GetParam().file), std::nullopt, 150.0f, base);
    EXPECT_EQ(spheres.size(), GetParam().spheres);
    EXPECT_EQ(spheres, cloudSpheres(cloudFile(GetParam().file), std::nullopt, 150.0f, base));

    const CloudBox box = boxOf(spheres);
    const glm::vec3 extent = box.high - box.low;
    EXPECT_NEAR(std::max({extent.x, extent.y, extent.z}), 150.0f, 1e-3f);
    EXPECT_NEAR(box.low.y, base.y, 1e-3f);
    EXPECT_NEAR(0.5f * (box.low.x + box.high.x), base.x, 1e-3f);
    EXPECT_NEAR(0.5f * (box.low.z + box.high.z), base.z, 1e-3f);
    float lowest = 1.0f, highest = 0.0f;
    for (const CloudSphere& s : spheres) {
        EXPECT_GT(s.radius, 0.0f);
        lowest = std::min(lowest, s.height);
        highest = std::max(highest, s.height);
    }
    EXPECT_EQ(lowest, 0.0f);
    EXPECT_EQ(highest, 1.0f);
}

INSTANTIATE_TEST_SUITE_P(Clouds, CloudLayoutTest,
                         testing::Values(LayoutCase{"explosion.lsys", 365}, LayoutCase{"curl.lsys", 363},
                                         LayoutCase{"spiral.lsys", 250}),
                         [](const testing::TestParamInfo<LayoutCase>& info) {
                             const std::string file = info.param.file;
                             return file.substr(0, file.find('.'));
                         });

// The cloud's seed replaces the file's: another seed, another cloud of as many spheres.
TEST(CloudSpheres, TheSeedReplacesTheFilesOwn) {
    const std::filesystem::path file = cloudFile("explosion.lsys");
    const std::vector<CloudSphere> own = cloudSpheres(file, std::nullopt, 100.0f, glm::vec3(0.0f));
    EXPECT_EQ(own, cloudSpheres(file, 7u, 100.0f, glm::vec3(0.0f))) << "explosion.lsys says seed: 7";
    const std::vector<CloudSphere> other = cloudSpheres(file, 8u, 100.0f, glm::vec3(0.0f));
    EXPECT_EQ(other.size(), own.size());
    EXPECT_NE(other, own);
}

// Only spheres make the cloud; each keeps its place in the turtle's order.
TEST(CloudSpheres, OnlySpheresCountAndTheirHeightsSpanTheCloud) {
    const auto file = test::writeFile("two.lsys", "Axiom: @O(2) F(5) @O(4) ~leaf(1)\n");
    const std::vector<CloudSphere> spheres = cloudSpheres(file, std::nullopt, 10.0f, glm::vec3(1.0f, 2.0f, 3.0f));
    ASSERT_EQ(spheres.size(), 2u);
    // Box: y from -1 to 7 (8 high), x and z from -2 to 2: scaled by 10/8.
    EXPECT_EQ(spheres[0].radius, 1.25f);
    EXPECT_EQ(spheres[1].radius, 2.5f);
    EXPECT_EQ(spheres[0].centre, glm::vec3(1.0f, 2.0f + 1.25f, 3.0f));
    EXPECT_EQ(spheres[1].centre, glm::vec3(1.0f, 2.0f + 6.0f * 1.25f, 3.0f));
    EXPECT_EQ(spheres[0].height, 0.0f);
    EXPECT_EQ(spheres[1].height, 1.0f);
    // The box's middle is at y 3 before scaling: one sphere below it, one above.
    EXPECT_EQ(spheres[0].outward, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(spheres[1].outward, glm::vec3(0.0f, 1.0f, 0.0f));
}

struct BadCloud {
    const char* name;
    const char* lsystem;
    const char* message;
};

void PrintTo(const BadCloud& bad, std::ostream* out) { *out << bad.name; }

class BadCloudTest : public testing::TestWithParam<BadCloud> {};

TEST_P(BadCloudTest, FailsWithAMessage) {
    const auto file = test::writeFile("bad.lsys", GetParam().lsystem);
    try {
        cloudSpheres(file, std::nullopt, 100.0f, glm::vec3(0.0f));
        FAIL() << "made a cloud";
    } catch (const CloudError& e) {
        EXPECT_NE(std::string(e.what()).find(GetParam().message), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Clouds, BadCloudTest,
    testing::Values(BadCloud{"malformed", "Axiom: @O(2\n", "bad.lsys:1:"},
                    BadCloud{"no_sphere", "Axiom: F F\n", "draws no sphere"},
                    // 2¹⁴ spheres: past kMaxCloudSpheres, well within the module budget.
                    BadCloud{"too_many_spheres",
                             "derivation length: 14\nAxiom: A\nA --> [+A] f [-A]\ninterpretation:\nA --> @O(1)\n",
                             "draws more than 8192 spheres, the most a cloud may have"},
                    BadCloud{"module_budget", "derivation length: 40\nAxiom: @O(1) A\nA --> A A\n",
                             "fewer derivation steps"}),
    [](const testing::TestParamInfo<BadCloud>& info) { return std::string(info.param.name); });

Cloud cloudOf(std::vector<CloudSphere> spheres) {
    Cloud cloud;
    cloud.spheres = std::move(spheres);
    return cloud;
}

// Farthest first along the view direction, drifted by wind velocity × time;
// equal depths keep the clouds' order.
TEST(CloudBillboards, DriftWithTheWindAndSortFarthestFirst) {
    const std::vector<Cloud> clouds = {cloudOf({{{0, 100, -50}, 5, 0.0f}, {{0, 100, -300}, 8, 1.0f, {0, 0, -1}}}),
                                       cloudOf({{{40, 100, -50}, 6, 0.5f}, {{0, 100, -120}, 7, 0.25f}})};
    Wind wind;
    wind.speed = 2.0f;
    wind.directionDegrees = 90.0f; // toward +x
    const glm::vec3 camera(0.0f), forward(0.0f, 0.0f, -1.0f);
    const std::vector<gpu::CloudBillboard> billboards = cloudBillboards(clouds, wind, 10.0f, camera, forward);
    ASSERT_EQ(billboards.size(), 4u);
    const float radii[] = {8.0f, 7.0f, 5.0f, 6.0f}; // z -300, -120, then the two at -50 in cloud order
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(billboards[i].sphere.w, radii[i]) << i;
    EXPECT_NEAR(billboards[0].sphere.x, 20.0f, 1e-4f) << "2 m/s toward +x for 10 s";
    EXPECT_NEAR(billboards[0].sphere.z, -300.0f, 1e-4f);
    EXPECT_EQ(billboards[0].shade, glm::vec4(1, 0, 0, -1)) << "height, then which side of the cloud";
    EXPECT_EQ(billboards[1].shade.x, 0.25f);

    // Looking the other way reverses the order.
    const std::vector<gpu::CloudBillboard> behind = cloudBillboards(clouds, wind, 10.0f, camera, -forward);
    EXPECT_EQ(behind.front().sphere.w, 5.0f);
    EXPECT_EQ(behind.back().sphere.w, 8.0f);
    // At time 0 the spheres are where the scene put them.
    EXPECT_EQ(cloudBillboards(clouds, wind, 0.0f, camera, forward)[0].sphere, glm::vec4(0, 100, -300, 8));
}

} // namespace
} // namespace pf
