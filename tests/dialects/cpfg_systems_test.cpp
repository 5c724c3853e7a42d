// Small cpfg L-systems of our own (tests/dialects/cpfg_systems, its README
// says what each exercises), each derived here and compared, module for
// module with parameters within 1e-4 relative (firstDifference, as `lsys
// derive --compare`), with the string vlab's cpfg derives from it (cpfg 6.6
// built from vlab's sources, `cpfg -str`, pinned in NAME.cpfg.str). A file
// with a view file beside it (NAME.v) is read as a vlab object, as cpfg
// reads it with that view file; NAME.cpfg.homo.str, where there is one, is
// the string after the homomorphism (`cpfg -h -str`).

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <optional>
#include <set>
#include <string>

#include "lsystem/language/module_string.h"
#include "lsystem/language/parser.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/vlab/object.h"

namespace lsys {
namespace {

namespace fs = std::filesystem;

const fs::path kSystems = PLANTFIELD_CPFG_SYSTEMS_DIR;

// Every NAME.l of the folder.
const char* const kSystemNames[] = {
    "bracket_predecessor",
    "consider_right_context",
    "contexts_consider",
    "contexts_ignore",
    "continuation",
    "decomposition_axiom",
    "functions_arrays",
    "global_blocks",
    "hash_line",
    "headers",
    "homomorphism_queries",
    "left_context_bracket",
    "local_variables",
    "movements",
    "preprocessor",
    "queries",
    "query_tropism",
    "query_up",
    "right_context_branches",
    "ring",
    "single_precision",
    "statement_blocks",
    "strict_predecessors",
    "turtle_modules",
    "turtle_queries",
};

// A cpfg string file of the folder; fails the test when it cannot be read.
std::string readCpfgString(const fs::path& path) {
    std::string problem;
    std::string text = readTextFile(path.string(), problem);
    EXPECT_TRUE(problem.empty()) << path << ": " << problem;
    EXPECT_FALSE(text.empty()) << path;
    return text;
}

class CpfgSystems : public ::testing::TestWithParam<const char*> {};

// The L-system reads (with its view file, when it has one) and derives, in
// its derivation length, the string cpfg derives; after the homomorphism,
// the string cpfg writes with -h.
TEST_P(CpfgSystems, DeriveAsCpfgDoes) {
    const std::string name = GetParam();
    const vlab::PlantFile plant = vlab::loadPlant(kSystems / (name + ".l"));
    ASSERT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    const Grammar& grammar = plant.parsed.grammar;

    const ModuleString string = derive(grammar);
    const std::optional<std::string> difference =
        firstDifference(string, grammar.symbols, readCpfgString(kSystems / (name + ".cpfg.str")));
    EXPECT_FALSE(difference) << *difference;

    const fs::path homomorphism = kSystems / (name + ".cpfg.homo.str");
    if (!fs::exists(homomorphism)) return;
    const std::optional<std::string> homomorphismDifference =
        firstDifference(applyInterpretation(grammar, string), grammar.symbols, readCpfgString(homomorphism));
    EXPECT_FALSE(homomorphismDifference) << "after the homomorphism: " << *homomorphismDifference;
}

std::string systemName(const ::testing::TestParamInfo<const char*>& info) { return info.param; }

INSTANTIATE_TEST_SUITE_P(, CpfgSystems, ::testing::ValuesIn(kSystemNames), systemName);

// Every L-system of the folder is listed above, and each has cpfg's string.
TEST(CpfgSystemsFolder, EverySystemIsListedWithCpfgsString) {
    std::set<std::string> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(kSystems))
        if (entry.path().extension() == ".l") files.insert(entry.path().stem().string());
    const std::set<std::string> listed(std::begin(kSystemNames), std::end(kSystemNames));
    EXPECT_EQ(files, listed);
    for (const std::string& name : listed) EXPECT_TRUE(fs::exists(kSystems / (name + ".cpfg.str"))) << name;
}

} // namespace
} // namespace lsys
