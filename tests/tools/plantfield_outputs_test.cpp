// plantfield never writes over a file it reads (tools/plantfield/output_check.h):
// --capture, --video, --export, --export-placements and --out-dir's frames onto the scene, through
// a link to it, onto a species' plant file or a vlab object's view and colour
// map are refused with exit 2 before any frame, the input left as it was.
#include "input_refusal.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace pf::test::plantfield_outputs {
namespace {

namespace fs = std::filesystem;

const std::string kPlantfield = PLANTFIELD_BIN;
const fs::path kData = PLANTFIELD_DATA_DIR;

TEST(PlantfieldOutputs, CaptureOntoTheSceneIsRefused) {
    const fs::path scene = bushScene(emptyTestFolder("plantfield_outputs"), kData);
    expectRefusedAsInput(kPlantfield + " " + scene.string() + " --size 64x64 --capture " + scene.string(), scene);
}

TEST(PlantfieldOutputs, OutputsThroughALinkToTheSceneAreRefused) {
    const fs::path dir = emptyTestFolder("plantfield_outputs");
    const fs::path scene = bushScene(dir, kData);
    for (const std::string output : {"--frames 2 --size 64x64 --video link.mp4", "--export link.glb",
                                     "--export-placements link.csv", "--export-placements link.json"}) {
        const fs::path link = dir / output.substr(output.find("link"));
        fs::create_symlink(scene, link);
        const std::string flags = output.substr(0, output.find("link"));
        expectRefusedAsInput(kPlantfield + " " + scene.string() + " " + flags + link.string(), scene);
    }
}

TEST(PlantfieldOutputs, SequenceFrameOntoTheSceneIsRefused) {
    const fs::path dir = emptyTestFolder("plantfield_outputs");
    const fs::path scene = bushScene(dir, kData);
    fs::create_directory(dir / "seq");
    fs::create_symlink(scene, dir / "seq" / "frame_0001.png");
    expectRefusedAsInput(
        kPlantfield + " " + scene.string() + " --frames 2 --size 64x64 --out-dir " + (dir / "seq").string(), scene);
    EXPECT_FALSE(fs::exists(dir / "seq" / "frame_0000.png")); // refused before any frame
}

// Known only once the scene is loaded: checked again before any work.
TEST(PlantfieldOutputs, OutputsOntoASpeciesPlantFileAreRefused) {
    const fs::path dir = emptyTestFolder("plantfield_outputs");
    const fs::path scene = bushScene(dir, kData);
    fs::create_symlink(dir / "bush.lsys", dir / "bush.csv");
    expectRefusedAsInput(kPlantfield + " " + scene.string() + " --export-placements " + (dir / "bush.csv").string(),
                         dir / "bush.lsys");
    fs::create_hard_link(dir / "bush.lsys", dir / "bush.png");
    expectRefusedAsInput(kPlantfield + " " + scene.string() + " --size 64x64 --capture " + (dir / "bush.png").string(),
                         dir / "bush.lsys");
}

TEST(PlantfieldOutputs, PreviewOntoAVlabObjectsViewOrColourMapIsRefused) {
    const fs::path dir = emptyTestFolder("plantfield_outputs");
    const fs::path tree = dir / "tree";
    fs::copy(kData / "plants" / "abop" / "fig2_6a_monopodial_tree", tree, fs::copy_options::recursive);
    for (const char* file : {"plant.v", "plant.map"}) {
        const fs::path link = dir / (std::string(file) + ".png");
        fs::create_symlink(tree / file, link);
        expectRefusedAsInput(kPlantfield + " --plant " + tree.string() + " --steps 3 --size 64x64 --capture " +
                                 link.string(),
                             tree / file);
    }
}

} // namespace
} // namespace pf::test::plantfield_outputs
