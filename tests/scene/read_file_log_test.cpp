// lsys::ReadFileLog (lsystem/common/file_reader.h) over a field's build, as
// plantfield --watch uses it: the files logged are the files the loaders
// read — the scene file, its terrain image, a vlab object's L-system, view
// file, colour map and surface — and a build that fails still logs the file
// at fault.
#include "engine/image/image.h"
#include "engine/scene/field_content.h"
#include "lsystem/common/file_reader.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

// One flat bilinear patch, a unit square in x and y (cpfg's surface format, docs/VLAB.md).
const char* const kFlatLeaf = "0 1 0 1 0 0\n"
                              "PRECISION S: 2 T: 2\n"
                              "CONTACT POINT  X: 0 Y: 0 Z: 0\n"
                              "END POINT  X: 0 Y: 1 Z: 0\n"
                              "HEADING  X: 0 Y: 1 Z: 0\n"
                              "UP  X: 0 Y: 0 Z: 1\n"
                              "SIZE: 1\n"
                              "Patch_1\n"
                              "TOP COLOR: 1 DIFFUSE: 0.00 BOTTOM COLOR: 1 DIFFUSE: 0.00\n"
                              "AL: ~ A: ~ AR: ~ \nL: ~ R: ~ \nBL: ~ B: ~ BR: ~ \n"
                              "0 0 0  0.33 0 0  0.67 0 0  1 0 0\n"
                              "0 0.33 0  0.33 0.33 0  0.67 0.33 0  1 0.33 0\n"
                              "0 0.67 0  0.33 0.67 0  0.67 0.67 0  1 0.67 0\n"
                              "0 1 0  0.33 1 0  0.67 1 0  1 1 0\n";

// A vlab object folder `object` in the test's folder: plant.l drawing the
// leaf surface, plant.v naming it, a colour map. Returns the folder.
fs::path writeObject(const std::string& lsystem) {
    writeFile("object/plant.l", lsystem);
    writeFile("object/plant.v", "angle increment: 30\nsurface: l leaf.s 1\n");
    writeFile("object/leaf.s", kFlatLeaf);
    writeFile("object/plant.map", std::string(768, '\x60'));
    return testFolder() / "object";
}

constexpr const char* kObjectLsystem = "Lsystem: 1\nderivation length: 2\nAxiom: A\nA --> F[+~l]A\nendlsystem\n";

// The scene file of the object on an image terrain, with the paths it names.
fs::path writeSceneOfObject() {
    RgbaImage ground{4, 4, std::vector<uint8_t>(4 * 4 * 4, 128)};
    writePng((testFolder() / "ground.png").string(), ground);
    return writeFile("scene.json", R"({
  "terrain": { "size": 20, "image": { "path": "ground.png", "height_scale": 2 } },
  "species": [ { "name": "leafy", "lsystem": "object", "placement": { "instances": [ { "position": [0, 0] } ] } } ]
})");
}

bool logged(const std::vector<fs::path>& paths, const fs::path& file) {
    return std::find(paths.begin(), paths.end(), file.lexically_normal()) != paths.end();
}

TEST(ReadFileLog, ASceneBuildLogsEveryFileItRead) {
    const fs::path object = writeObject(kObjectLsystem);
    const fs::path scene = writeSceneOfObject();
    const lsys::ReadFileLog read;
    const FieldContent content = buildFieldContent(loadScene(scene.string()));
    ASSERT_EQ(content.plants.size(), 1u);
    for (const fs::path& file : {scene, testFolder() / "ground.png", object / "plant.l", object / "plant.v",
                                 object / "leaf.s", object / "plant.map"})
        EXPECT_TRUE(logged(read.paths(), file)) << file << " was read but not logged";
    EXPECT_FALSE(logged(read.paths(), testFolder() / "unrelated.txt"));
}

// A malformed L-system: the build throws, and the file is in the log, so a
// watcher sees its next save.
TEST(ReadFileLog, AFailedBuildStillLogsTheFileAtFault) {
    const fs::path object = writeObject("Lsystem: 1\nderivation length: 2\nAxiom: A\nA --> F(1+*)[+~l]A\nendlsystem\n");
    const fs::path scene = writeSceneOfObject();
    const lsys::ReadFileLog read;
    EXPECT_THROW(buildFieldContent(loadScene(scene.string())), SceneError);
    EXPECT_TRUE(logged(read.paths(), object / "plant.l"));
    EXPECT_TRUE(logged(read.paths(), scene));
}

// Logs are per thread and nest: a read on another thread is not in this
// thread's log; an inner log sees only its own reads, the outer both.
TEST(ReadFileLog, LogsArePerThreadAndNest) {
    const fs::path first = writeFile("first.txt", "1"), second = writeFile("second.txt", "2"),
                   elsewhere = writeFile("elsewhere.txt", "3");
    const lsys::ReadFileLog outer;
    lsys::readFileUpTo(first, 16);
    {
        const lsys::ReadFileLog inner;
        lsys::readFileUpTo(second, 16);
        std::thread([&] { lsys::readFileUpTo(elsewhere, 16); }).join();
        EXPECT_EQ(inner.paths(), std::vector<fs::path>{second});
    }
    EXPECT_EQ(outer.paths(), (std::vector<fs::path>{first, second}));
}

} // namespace
} // namespace pf::test
