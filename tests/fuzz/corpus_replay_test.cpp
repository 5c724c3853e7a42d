// Replays every fuzz corpus input (crashers the fuzzer found included, once
// fixed) and every shipped plant through the parser, rewriter and turtle.
// Under the regular build this proves none of them crash or hang any more.
#include "lsys_fuzz_target.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputsUnder(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const fs::path& dir, size_t atLeast) {
    const std::vector<fs::path> files = inputsUnder(dir);
    ASSERT_GE(files.size(), atLeast) << dir;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        pf::fuzz::runLsysInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
}

TEST(FuzzCorpus, EveryCorpusInputRunsToCompletion) { replay(PLANTFIELD_FUZZ_DIR "/corpus", 20); }

TEST(FuzzCorpus, EveryPastCrasherRunsToCompletion) { replay(PLANTFIELD_FUZZ_DIR "/crashers", 1); }

TEST(FuzzCorpus, EveryShippedPlantRunsToCompletion) { replay(PLANTFIELD_DATA_DIR "/plants", 10); }

} // namespace
