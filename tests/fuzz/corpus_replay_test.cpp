// Replays every fuzz corpus input (crashers the fuzzers found included, once
// fixed) and every shipped file of each kind through its fuzz target: plant
// files and terrain L-systems through parser, rewriter and turtle, scene files through the scene
// loader, component plants through their reader and builder, glTF files through the surface loader, a vlab object's
// view, function, surface and colour files through their readers, ramification matrices through generation and
// the turtle, terrain L-systems into mountains and cloud L-systems into spheres. Under the regular build this proves
// none of them crash or hang any more; under the sanitizer build (tools/sanitize.sh) that none reads or writes out of
// bounds.
#include "fuzz_targets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Target = void (*)(const uint8_t*, size_t);

// The files under `dir` (those ending in `extension`, when given).
std::vector<fs::path> inputsUnder(const fs::path& dir, std::string_view extension) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(Target target, const fs::path& dir, size_t atLeast, std::string_view extension = {}) {
    const std::vector<fs::path> files = inputsUnder(dir, extension);
    ASSERT_GE(files.size(), atLeast) << dir;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        target(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
}

const fs::path kFuzz = PLANTFIELD_FUZZ_DIR;
const fs::path kData = PLANTFIELD_DATA_DIR;

TEST(FuzzCorpus, EveryPlantCorpusInputRunsToCompletion) { replay(pf::fuzz::runLsysInput, kFuzz / "corpus/lsys", 20); }

TEST(FuzzCorpus, EveryPastPlantCrasherRunsToCompletion) { replay(pf::fuzz::runLsysInput, kFuzz / "crashers/lsys", 1); }

TEST(FuzzCorpus, EveryShippedPlantRunsToCompletion) { replay(pf::fuzz::runLsysInput, kData / "plants", 10); }

TEST(FuzzCorpus, EveryShippedTerrainLsystemRunsToCompletion) { replay(pf::fuzz::runLsysInput, kData / "terrain", 3); }

TEST(FuzzCorpus, EverySceneCorpusInputRunsToCompletion) { replay(pf::fuzz::runSceneInput, kFuzz / "corpus/scene", 20); }

TEST(FuzzCorpus, EveryShippedSceneRunsToCompletion) { replay(pf::fuzz::runSceneInput, kData / "scenes", 5); }

TEST(FuzzCorpus, EveryComponentsCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runComponentsInput, kFuzz / "corpus/components", 20);
}

TEST(FuzzCorpus, EveryShippedComponentPlantRunsToCompletion) {
    replay(pf::fuzz::runComponentsInput, kData / "components", 3);
}

TEST(FuzzCorpus, EveryGltfCorpusInputRunsToCompletion) { replay(pf::fuzz::runGltfInput, kFuzz / "corpus/gltf", 20); }

TEST(FuzzCorpus, EveryPastGltfCrasherRunsToCompletion) { replay(pf::fuzz::runGltfInput, kFuzz / "crashers/gltf", 1); }

TEST(FuzzCorpus, EveryShippedMeshRunsToCompletion) { replay(pf::fuzz::runGltfInput, kData / "meshes", 2); }

TEST(FuzzCorpus, EveryViewCorpusInputRunsToCompletion) { replay(pf::fuzz::runViewInput, kFuzz / "corpus/view", 20); }

TEST(FuzzCorpus, EveryShippedViewFileRunsToCompletion) { replay(pf::fuzz::runViewInput, kData / "plants", 10, ".v"); }

TEST(FuzzCorpus, EveryFunctionCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runFuncInput, kFuzz / "corpus/func", 20);
}

TEST(FuzzCorpus, EveryPastFunctionCrasherRunsToCompletion) {
    replay(pf::fuzz::runFuncInput, kFuzz / "crashers/func", 1);
}

TEST(FuzzCorpus, EverySurfaceCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runSurfaceInput, kFuzz / "corpus/surface", 10);
}

TEST(FuzzCorpus, EveryColorCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runColorInput, kFuzz / "corpus/colour", 10);
}

TEST(FuzzCorpus, EveryShippedColorMapRunsToCompletion) {
    replay(pf::fuzz::runColorInput, kData / "plants", 10, ".map");
}

TEST(FuzzCorpus, EveryRamificationCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runRamificationInput, kFuzz / "corpus/ramification", 10);
}

TEST(FuzzCorpus, EveryShippedRamificationMatrixRunsToCompletion) {
    replay(pf::fuzz::runRamificationInput, kData / "ramified", 3);
}

TEST(FuzzCorpus, EveryTerrainCorpusInputRunsToCompletion) {
    replay(pf::fuzz::runTerrainInput, kFuzz / "corpus/terrain", 10);
}

TEST(FuzzCorpus, EveryPastTerrainCrasherRunsToCompletion) {
    replay(pf::fuzz::runTerrainInput, kFuzz / "crashers/terrain", 1);
}

TEST(FuzzCorpus, EveryShippedTerrainLsystemMakesMountains) { replay(pf::fuzz::runTerrainInput, kData / "terrain", 3); }

TEST(FuzzCorpus, EveryCloudCorpusInputRunsToCompletion) { replay(pf::fuzz::runCloudInput, kFuzz / "corpus/cloud", 10); }

TEST(FuzzCorpus, EveryShippedCloudRunsToCompletion) { replay(pf::fuzz::runCloudInput, kData / "clouds", 3); }

} // namespace
