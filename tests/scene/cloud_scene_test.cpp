// The "clouds" key of a scene file (docs/SCENE_FORMAT.md): its clouds read
// with their spheres, paths resolved against the scene file, the cloud
// files in the log --watch follows, and a malformed cloud L-system reported
// at the scene's line and column. Keys and values at fault are BadSceneTest
// cases (scene_error_test.cpp).
#include "engine/scene/scene.h"
#include "lsystem/common/file_reader.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pf {
namespace {

namespace fs = std::filesystem;

std::string sceneWithClouds(const std::string& clouds) {
    return "{\n  \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM " } ],\n  \"clouds\": [\n" + clouds + "\n  ]\n}";
}

TEST(CloudScene, CloudsReadWithTheirSpheresRelativeToTheSceneFile) {
    test::writeFile("sky/puff.lsys", "Axiom: @O(2) f(1) @O(3)\n");
    const fs::path file = test::writeFile(
        "scene.json",
        sceneWithClouds("    { \"lsystem\": \"sky/puff.lsys\", \"position\": [5, 200, -30], \"size\": 40 },\n"
                        "    { \"lsystem\": \"" PLANTFIELD_DATA_DIR "/clouds/curl.lsys\", \"position\": "
                        "[0, 150, 0], \"seed\": 2, \"shadow\": true }"));
    const Scene scene = loadScene(file);
    ASSERT_EQ(scene.clouds.size(), 2u);
    const Cloud& puff = scene.clouds[0];
    EXPECT_EQ(puff.lsystem, test::testFolder() / "sky/puff.lsys");
    EXPECT_EQ(puff.position, glm::vec3(5, 200, -30));
    EXPECT_EQ(puff.size, 40.0f);
    EXPECT_EQ(puff.seed, std::nullopt);
    EXPECT_FALSE(puff.shadow);
    EXPECT_EQ(puff.spheres, cloudSpheres(puff.lsystem, std::nullopt, 40.0f, puff.position));
    EXPECT_EQ(puff.spheres.size(), 2u);
    const Cloud& curl = scene.clouds[1];
    EXPECT_EQ(curl.size, Cloud{}.size);
    EXPECT_EQ(curl.seed, 2u);
    EXPECT_TRUE(curl.shadow);
    EXPECT_EQ(curl.spheres, cloudSpheres(curl.lsystem, 2u, curl.size, curl.position));
    EXPECT_TRUE(loadScene(test::writeFile("none.json", sceneWithClouds(""))).clouds.empty());
}

bool logged(const std::vector<fs::path>& paths, const fs::path& file) {
    return std::find(paths.begin(), paths.end(), file.lexically_normal()) != paths.end();
}

// The cloud's file is in the log whether it makes a cloud or not, so
// plantfield --watch rebuilds when it is saved.
TEST(CloudScene, CloudFilesAreLoggedForWatching) {
    const fs::path cloud = test::writeFile("puff.lsys", "Axiom: @O(2)\n");
    const fs::path scene =
        test::writeFile("scene.json", sceneWithClouds("    { \"lsystem\": \"puff.lsys\", \"position\": [0, 100, 0] }"));
    {
        const lsys::ReadFileLog read;
        loadScene(scene);
        EXPECT_TRUE(logged(read.paths(), cloud));
    }
    test::writeFile("puff.lsys", "Axiom: @O(2\n");
    const lsys::ReadFileLog read;
    EXPECT_THROW(loadScene(scene), SceneError);
    EXPECT_TRUE(logged(read.paths(), cloud));
}

// The scene's line and column of the "lsystem" value first, then the
// L-system's own diagnostic with its file, line and column.
TEST(CloudScene, AMalformedCloudIsReportedAtItsSceneKeyAndInItsFile) {
    const fs::path cloud = test::writeFile("broken.lsys", "Axiom: @O(2)\nA --> @O(1 +* 2)\n");
    const std::string text = sceneWithClouds("    { \"lsystem\": \"broken.lsys\", \"position\": [0, 100, 0] }");
    const fs::path scene = test::writeFile("scene.json", text);
    try {
        loadScene(scene);
        FAIL() << "loaded a malformed cloud";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(scene.string() + ":" + test::lineColumnOf(text, "\"broken.lsys\"") +
                                 ": /clouds/0/lsystem makes no cloud: ",
                             0),
                  0u)
            << what;
        EXPECT_NE(what.find(cloud.string() + ":2:"), std::string::npos) << what;
    }
}

// Nine clouds of 8 192 spheres each pass the budget of one cloud but not
// the scene's, at the ninth.
TEST(CloudScene, TheScenesCloudsHaveASphereBudget) {
    test::writeFile("full.lsys", "derivation length: 13\nAxiom: A\nA --> [+A] f [-A]\ninterpretation:\nA --> @O(1)\n");
    std::string clouds;
    for (int i = 0; i < 9; ++i)
        clouds += std::string(i ? ",\n" : "") + "    { \"lsystem\": \"full.lsys\", \"position\": [" +
                  std::to_string(i) + ", 100, 0] }";
    const std::string text = sceneWithClouds(clouds);
    try {
        loadScene(test::writeFile("scene.json", text));
        FAIL() << "loaded more cloud spheres than a scene may have";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(test::lineColumnOf(text, "{ \"lsystem\": \"full.lsys\", \"position\": [8") +
                            ": /clouds/8 brings the scene's clouds to 73728 spheres, more than the 65536"),
                  std::string::npos)
            << what;
    }
}

} // namespace
} // namespace pf
