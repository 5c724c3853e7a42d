// .ram.json files, Tankard's balance slider and the generation guards.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "lsystem/ramification/ramification_file.h"
#include "ramification_test_support.h"

namespace lsys {
namespace {

// The first diagnostic of a file that must be refused, as "line:column: message".
std::string refusal(const std::string& text) {
    const RamificationFile file = parseRamification(text, "t.ram.json");
    EXPECT_FALSE(file.tree) << text;
    if (file.diagnostics.empty()) return "";
    const Diagnostic& d = file.diagnostics[0];
    return std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message;
}

RamificationTree accepted(const std::string& text) {
    const RamificationFile file = parseRamification(text, "t.ram.json");
    EXPECT_TRUE(file.tree) << formatDiagnostics(file.diagnostics, file.source);
    return file.tree.value_or(RamificationTree{});
}

// Tankard 2001, §4.2.1.2: y = 1 + cos(π (j / i − b / 100)), rows normalised.
TEST(RamificationBalance, RowsFollowTheSinusoidNormalised) {
    const RamificationMatrix matrix = balancedMatrix(3, 50.0);
    EXPECT_EQ(matrix.p[0], (std::vector<double>{1.0}));
    EXPECT_NEAR(matrix.p[1][0], 2.0 / 3.0, 1e-12); // y = 2 and 1
    EXPECT_NEAR(matrix.p[1][1], 1.0 / 3.0, 1e-12);
    const double y = 1.0 + std::cos(std::numbers::pi / 6.0); // j = 1 and 2 of row 3; j = 3 gives 1
    EXPECT_NEAR(matrix.p[2][0], y / (2.0 * y + 1.0), 1e-12);
    EXPECT_NEAR(matrix.p[2][1], y / (2.0 * y + 1.0), 1e-12);
    EXPECT_NEAR(matrix.p[2][2], 1.0 / (2.0 * y + 1.0), 1e-12);
    // Balance 100 favours the right of each row (a perfect tree), 0 the left (a trunk).
    EXPECT_GT(balancedMatrix(5, 100.0).p[4][4], balancedMatrix(5, 100.0).p[4][0]);
    EXPECT_EQ(balancedMatrix(5, 0.0).p[4][4], 0.0);
}

TEST(RamificationGuards, ZeroRowsSplitAndEveryAxisEnds) {
    RamificationMatrix matrix;
    matrix.p = {{7.0}, {0.0, 0.0}, {2.0, 2.0, 0.0}, {1.0, 1.0, 1.0, 1.0}};
    const RamificationMatrix guarded = guardedMatrix(matrix);
    EXPECT_EQ(guarded.p[0], (std::vector<double>{1.0}));
    EXPECT_EQ(guarded.p[1], (std::vector<double>{0.0, 1.0}));
    const double side = (1.0 - kMinSplitProbability) / 2.0;
    EXPECT_NEAR(guarded.p[2][0], side, 1e-12);
    EXPECT_NEAR(guarded.p[2][1], side, 1e-12);
    EXPECT_NEAR(guarded.p[2][2], kMinSplitProbability, 1e-12);
    for (double value : guarded.p[3]) EXPECT_NEAR(value, 0.25, 1e-12);
}

TEST(RamificationFile, ReadsAMatrixAndItsGrowth) {
    const RamificationTree tree = accepted(R"({"orders": 3, "a": [8, 5, 2], "p": [[1], [0.6, 0.4], [0.5, 0, 0.5]],
        "twist": 90, "length": 0.5, "width": 0.25, "width_exponent": 1, "split_angle": 35, "main_angle": 10,
        "side_angle": 60, "seed": 7, "max_branches": 1000, "description": "Tankard's Figure 3"})");
    EXPECT_EQ(tree.matrix.p, (std::vector<std::vector<double>>{{1}, {0.6, 0.4}, {0.5, 0, 0.5}}));
    EXPECT_EQ(tree.growth.twist, 90.0);
    EXPECT_EQ(tree.growth.length, 0.5);
    EXPECT_EQ(tree.growth.width, 0.25);
    EXPECT_EQ(tree.growth.widthExponent, 1.0);
    EXPECT_EQ(tree.growth.splitAngle, 35.0);
    EXPECT_EQ(tree.growth.mainAngle, 10.0);
    EXPECT_EQ(tree.growth.sideAngle, 60.0);
    EXPECT_EQ(tree.seed, 7u);
    EXPECT_EQ(tree.maxBranches, 1000u);
    // seed and max_branches are 64-bit.
    const RamificationTree wide =
        accepted(R"({"p": [[1]], "seed": 18446744073709551615, "max_branches": 1099511627776})");
    EXPECT_EQ(wide.seed, std::numeric_limits<uint64_t>::max());
    EXPECT_EQ(wide.maxBranches, uint64_t(1) << 40);
    const RamificationTree habit = accepted(R"({"p": [[1]], "side_angle_min": 75, "phyllotaxis": 137.5,
        "droop": 0.02, "stems": 5, "stem_angle": 25, "foliage": {"kind": "needles", "orders": 3, "clusters": 4,
        "per_cluster": 5, "size": 0.2, "angle": 40, "width": 0.05}})");
    EXPECT_EQ(habit.growth.minSideAngle, 75.0);
    EXPECT_EQ(habit.growth.phyllotaxis, 137.5);
    EXPECT_EQ(habit.growth.droop, 0.02);
    EXPECT_EQ(habit.growth.stems, 5u);
    EXPECT_EQ(habit.growth.stemAngle, 25.0);
    EXPECT_EQ(habit.foliage.kind, RamificationFoliage::Kind::Needles);
    EXPECT_EQ(habit.foliage.maxOrder, 3u);
    EXPECT_EQ(habit.foliage.clusters, 4u);
    EXPECT_EQ(habit.foliage.perCluster, 5u);
    EXPECT_EQ(habit.foliage.size, 0.2);
    EXPECT_EQ(habit.foliage.angle, 40.0);
    EXPECT_EQ(habit.foliage.needleWidth, 0.05);
    EXPECT_EQ(accepted(R"({"p": [[1]], "foliage": {"kind": "leaves"}})").foliage.kind,
              RamificationFoliage::Kind::Leaves);
    EXPECT_EQ(accepted(R"({"p": [[1]]})").foliage.kind, RamificationFoliage::Kind::None);
    // depth removes rows; balance makes a matrix of any depth.
    EXPECT_EQ(accepted(R"({"p": [[1], [0.6, 0.4], [0.5, 0, 0.5]], "depth": 2})").matrix.orders(), 2u);
    EXPECT_EQ(accepted(R"({"balance": 50, "depth": 3})").matrix.p, balancedMatrix(3, 50.0).p);
}

TEST(RamificationFile, RefusesBadFilesAtTheirLineAndColumn) {
    // The file's text, and its first diagnostic as "line:column: message".
    const std::vector<std::pair<std::string, std::string>> refusals = {
        {"{\n  \"p\": [[1], [0.5, 0.5]]\n  \"twist\": 3\n}",
         "3:9: syntax error while parsing object - unexpected string literal; expected '}'"},
        {"{\n  \"p\": [[1], [0.5, 0.5]],\n  \"twst\": 3\n}", "3:3: /twst is an unknown key; did you mean \"twist\"?"},
        {"{\"p\": [[1],\n      [0.5, -1]]}", "2:13: /p/1/1 must be a number ≥ 0 (got -1)"},
        {"{\"p\": [[1], [0.5]]}", "1:13: /p/1 must hold 2 numbers (p_21 ... p_22), not 1"},
        {"{\"p\": [[1], 2]}", "1:13: /p/1 must be an array of 2 numbers (p_21 ... p_22) (got 2)"},
        {"{\"p\": []}", "1:7: /p must hold 1 to 64 rows, row k holding k numbers (got 0 rows)"},
        {"{\"p\": [[1]], \"balance\": 3, \"depth\": 2}",
         "1:14: /balance cannot be given together with \"p\": give the matrix or Tankard's balance slider"},
        {"{\n}", "1:1: the ramification tree needs \"p\" (the matrix) or \"balance\" with \"depth\""},
        {"{\"balance\": 3}", "1:13: /balance needs \"depth\", the number of orders"},
        {"{\"balance\": 130, \"depth\": 2}", "1:13: /balance must be a number in [0, 100] (got 130)"},
        {"{\"p\": [[1], [0, 1]], \"depth\": 3}",
         "1:31: /depth must be at most the 2 rows of \"p\" (it removes rows; \"balance\" makes any depth)"},
        {"{\"p\": [[1]], \"orders\": 2}", "1:24: /orders must be 1, the rows of \"p\" (or \"depth\" with \"balance\")"},
        {"{\"p\": [[1]], \"a\": [1, 2]}", "1:19: /a must hold the 1 branch counts a_1 ... a_K, not 2"},
        {"{\"p\": [[1]], \"a\": [-1]}", "1:20: /a/0 must be an integer ≥ 0 (got -1)"},
        {"{\"balance\": 3, \"depth\": 65}", "1:25: /depth must be an integer in [1, 64] (got 65)"},
        {"{\"p\": [[1]], \"max_branches\": 0}", "1:30: /max_branches must be an integer in [1, 1099511627776] (got 0)"},
        {"[1]", "1:1: the ramification tree must be an object (got [1])"},
        {"{\"p\": [[1]], \"foliage\": {\"kind\": \"fronds\"}}",
         "1:34: /foliage/kind must be \"leaves\" or \"needles\" (got \"fronds\")"},
        {"{\"p\": [[1]], \"foliage\": {\"kind\": \"needle\"}}",
         "1:34: /foliage/kind must be \"leaves\" or \"needles\" (got \"needle\"); did you mean \"needles\"?"},
        {"{\"p\": [[1]], \"foliage\": {\"size\": 1}}", "1:25: /foliage needs \"kind\": \"leaves\" or \"needles\""},
        {"{\"p\": [[1]], \"foliage\": {\"kind\": \"leaves\", \"clusterz\": 2}}",
         "1:44: /foliage/clusterz is an unknown key; did you mean \"clusters\"?"},
        {"{\"p\": [[1]], \"foliage\": {\"kind\": \"leaves\", \"clusters\": 0}}",
         "1:56: /foliage/clusters must be an integer in [1, 64] (got 0)"},
        {"{\"p\": [[1]], \"stems\": 0}", "1:23: /stems must be an integer in [1, 64] (got 0)"},
        {"{\"p\": [[1]], \"foliage\": 3}", "1:25: /foliage must be an object (got 3)"},
        {"{\"p\": [[1]], \"seed\": -1}", "1:22: /seed must be an integer ≥ 0 (got -1)"},
        {"{\"p\": [[1]], \"seed\": 1.5}", "1:22: /seed must be an integer ≥ 0 (got 1.5)"},
        {"{\"p\": [[1]], \"description\": 3}", "1:29: /description must be a string (got 3)"},
        {"{\"p\": [[1]], \"p\": [[1]]}", "1:14: \"p\" is given twice in one object"},
        {"\xEF\xBB\xBF{\"p\": [[1]], \"seeds\": 1}", "1:17: /seeds is an unknown key; did you mean \"seed\"?"},
        {"{\"p\": " + std::string(100000, '['), "1:14: the ramification tree nests deeper than 8 levels"},
        {"{\"p\": [[1], [0.5, 0.5], \"]]]]\" [[[[[[[]]]]]]]}",
         "1:38: the ramification tree nests deeper than 8 levels"},
    };
    for (const auto& [text, expected] : refusals) EXPECT_EQ(refusal(text), expected) << text.substr(0, 80);
    const RamificationFile missing = readRamificationFile("/nonexistent/x.ram.json");
    ASSERT_EQ(missing.diagnostics.size(), 1u);
    EXPECT_NE(missing.diagnostics[0].message.find("x.ram.json"), std::string::npos);
}

// The species of data/ramified/ are valid files.
TEST(RamificationFile, DataSpeciesAreValid) {
    size_t species = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::dataPath("ramified"))) {
        if (!isRamificationFile(entry.path())) continue;
        SCOPED_TRACE(entry.path().string());
        const RamificationFile file = readRamificationFile(entry.path());
        EXPECT_TRUE(file.tree) << formatDiagnostics(file.diagnostics, file.source);
        ++species;
    }
    EXPECT_GE(species, 3u);
}

} // namespace
} // namespace lsys
