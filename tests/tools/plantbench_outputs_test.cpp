// plantbench never writes over a file it reads (outputsProblem in
// tools/plantbench/plantbench_options.h): --json, --csv and --plot onto the
// scene, through a link to it, or onto a species' plant file are refused with
// exit 2 before the measurements, the input left as it was.
#include "input_refusal.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace pf::test::plantbench_outputs {
namespace {

namespace fs = std::filesystem;

const std::string kPlantbench = PLANTBENCH_BIN;
const fs::path kData = PLANTFIELD_DATA_DIR;
const std::string kQuick = " --counts 10 --frames 1 --warmup 0 --size 64x36";

TEST(PlantbenchOutputs, JsonOntoTheSceneIsRefused) {
    const fs::path scene = bushScene(emptyTestFolder("plantbench_outputs"), kData);
    expectRefusedAsInput(kPlantbench + " " + scene.string() + kQuick + " --json " + scene.string(), scene);
}

TEST(PlantbenchOutputs, CsvThroughALinkToTheSceneIsRefused) {
    const fs::path dir = emptyTestFolder("plantbench_outputs");
    const fs::path scene = bushScene(dir, kData);
    fs::create_symlink(scene, dir / "sweep.csv");
    expectRefusedAsInput(kPlantbench + " " + scene.string() + kQuick + " --csv " + (dir / "sweep.csv").string(), scene);
}

// Known only once the field is built: checked again before it is measured.
TEST(PlantbenchOutputs, JsonOntoASpeciesPlantFileIsRefused) {
    const fs::path dir = emptyTestFolder("plantbench_outputs");
    const fs::path scene = bushScene(dir, kData);
    fs::create_hard_link(dir / "bush.lsys", dir / "sweep.json");
    expectRefusedAsInput(kPlantbench + " " + scene.string() + kQuick + " --json " + (dir / "sweep.json").string(),
                         dir / "bush.lsys");
}

} // namespace
} // namespace pf::test::plantbench_outputs
