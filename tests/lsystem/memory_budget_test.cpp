// The memory budget (lsystem/common/memory_budget.h): sizes as --memory-budget reads
// them, the error need() raises, and every stage of lsystem/ refusing work
// past the budget before it allocates.

#include <unistd.h>

#include <filesystem>
#include <string>

#include "lsystem/common/memory_budget.h"
#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/turtle/turtle.h"
#include "test_support.h"

namespace lsys::test {
namespace {

constexpr uint64_t kMiB = 1ull << 20;

// Runs `work`, which must throw MemoryBudgetError naming `stage`; returns the message.
template <typename Work>
std::string refusal(Work work, const std::string& stage) {
    try {
        work();
    } catch (const MemoryBudgetError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(stage + " needs "), std::string::npos) << message;
        EXPECT_NE(message.find("the limit is"), std::string::npos) << message;
        EXPECT_NE(message.find("--memory-budget"), std::string::npos) << message;
        return message;
    } catch (const std::exception& error) {
        ADD_FAILURE() << "expected a MemoryBudgetError, got: " << error.what();
        return {};
    }
    ADD_FAILURE() << "expected the " << stage << " to be refused";
    return {};
}

TEST(MemoryBudget, SizesAreBytesOrBinaryUnits) {
    EXPECT_EQ(parseByteSize("800000000"), 800000000u);
    EXPECT_EQ(parseByteSize("512M"), 512 * kMiB);
    EXPECT_EQ(parseByteSize("512m"), 512 * kMiB);
    EXPECT_EQ(parseByteSize("512MiB"), 512 * kMiB);
    EXPECT_EQ(parseByteSize("4G"), 4096 * kMiB);
    EXPECT_EQ(parseByteSize("4GB"), 4096 * kMiB);
    EXPECT_EQ(parseByteSize("1.5G"), 1536 * kMiB);
    EXPECT_EQ(parseByteSize("64K"), 65536u);
    EXPECT_EQ(parseByteSize("2T"), 2ull << 40);
    EXPECT_EQ(parseByteSize("100B"), 100u);
    for (const char* bad : {"", "0", "-1G", "G", "4X", "4GG", "4 G", "nan", "inf", "1e30", "16777216T", "0.1"})
        EXPECT_EQ(parseByteSize(bad), std::nullopt) << bad;
}

TEST(MemoryBudget, BytesAreFormattedForPeople) {
    EXPECT_EQ(formatBytes(800), "800 B");
    EXPECT_EQ(formatBytes(12 * kMiB), "12.0 MiB");
    EXPECT_EQ(formatBytes(3 * (1ull << 30) / 2), "1.5 GiB");
    EXPECT_EQ(formatBytes(1024 * kMiB - 1), "1.0 GiB");
    EXPECT_EQ(formatBytes(UINT64_MAX), "16.0 EiB");
}

TEST(MemoryBudget, NeedPastTheLimitNamesStageNeedAndLimit) {
    const MemoryBudget budget{512 * kMiB};
    EXPECT_NO_THROW(need(budget, "export", 512 * kMiB));
    const std::string message = refusal([&] { need(budget, "export", 3 * (1ull << 30)); }, "export");
    EXPECT_EQ(message, "memory budget: export needs 3.0 GiB, the limit is 512.0 MiB (set with --memory-budget)");
    // Just past the limit the rounded sizes would read alike: bytes then.
    EXPECT_NE(refusal([&] { need(budget, "turtle", 512 * kMiB + 1); }, "turtle").find("536870913 B"),
              std::string::npos);
    // A need too large to count saturates and is still refused.
    EXPECT_NE(refusal([&] { need(budget, "derivation", bytesTimes(UINT64_MAX / 2, 3)); }, "derivation")
                  .find("more than 16.0 EiB"),
              std::string::npos);
}

TEST(MemoryBudget, ByteArithmeticSaturates) {
    EXPECT_EQ(bytesTimes(1ull << 40, 1ull << 30), UINT64_MAX);
    EXPECT_EQ(bytesTimes(3, 7), 21u);
    EXPECT_EQ(bytesPlus(UINT64_MAX - 1, 2), UINT64_MAX);
    EXPECT_EQ(bytesPlus(2, 3), 5u);
}

TEST(MemoryBudget, DerivationCountsBytesNotOnlyModules) {
    const Grammar bush = loadOk("plants/fractal_bush.lsys"); // D0L: step 6 gives 711 532 modules
    DeriveOptions options = stepsOf(6);
    options.memory = {kMiB};
    refusal([&] { derive(bush, options); }, "derivation");
    options.memory = {16 * kMiB};
    EXPECT_EQ(derive(bush, options).size(), 711532u);

    const Grammar parametric = loadOk("plants/decreasing_tree.lsys"); // the general path, with parameters
    DeriveOptions general = stepsOf(16);
    general.memory = {kMiB};
    refusal([&] { derive(parametric, general); }, "derivation");
}

TEST(MemoryBudget, TurtleIsRefusedBeforeInterpreting) {
    const Grammar bush = loadOk("plants/fractal_bush.lsys");
    const ModuleString word = derive(bush, stepsOf(5)); // 32 768 segments
    const uint64_t need = turtleBytes(word, turtleCommands(bush.symbols));
    EXPECT_GE(need, 32768 * (sizeof(Primitive) + sizeof(Joint)));
    refusal([&] { plantFromGrammar(bush, word, SurfaceLibrary{}, {need - 1}); }, "turtle");
    EXPECT_EQ(plantFromGrammar(bush, word, SurfaceLibrary{}, {need}).primitives.size(), 32768u);
}

TEST(MemoryBudget, BGrammarOfADerivedWordIsRefusedBeforeCompressing) {
    const Grammar grammar = loadOk("plants/hogeweg_1_31a.lsys"); // context-sensitive: derived, then SEQUITUR
    BGrammarOptions options;
    options.interpreted = true;
    options.memory = {256 * 1024}; // the 6 910 modules derive in 27 KiB, SEQUITUR needs more
    refusal([&] { buildBGrammar(grammar, options); }, "b-grammar");
}

TEST(MemoryBudget, MemoisedBGrammarIsRefusedWhileItGrows) {
    // Every key of this chain is new: it makes keys, not nodes or items.
    const Grammar chain = parseOk("Axiom: A(0)\nA(x) --> B A(x+1)\nB --> F\n");
    BGrammarOptions options;
    options.steps = 100000;
    options.memory = {kMiB};
    refusal([&] { buildBGrammar(chain, options); }, "b-grammar");
}

TEST(MemoryBudget, InstanceGraphIsRefusedWhileItGrows) {
    // At 40 steps its objects outgrow a million (about 500 MB) before the object limit.
    const Grammar tree = loadOk("plants/monopodial_tree.lsys");
    BGrammarOptions words;
    words.steps = 40;
    words.interpreted = true;
    const BGrammar bgrammar = buildBGrammar(tree, words);
    InstanceGraphOptions options;
    options.memory = {64 * kMiB};
    refusal([&] { buildInstanceGraph(bgrammar, tree, options); }, "instance graph");
}

class ExportBudget : public ::testing::Test {
protected:
    void SetUp() override {
        const Grammar bush = loadOk("plants/fractal_bush.lsys");
        plant = plantFromGrammar(bush, derive(bush, stepsOf(4))); // 4 096 segments
        folder = std::filesystem::temp_directory_path() / ("memory_budget_" + std::to_string(::getpid()));
        std::filesystem::create_directories(folder);
    }
    void TearDown() override { std::filesystem::remove_all(folder); }

    PlantAsset plant;
    std::filesystem::path folder;
};

TEST_F(ExportBudget, EstimateFollowsTheSegmentsAndTheFormat) {
    const MeshSize meshes = bakedMeshSize(plant, MeshDetail{});
    // Eight sides with caps: 36 vertices and 96 indices a segment, 1 536 bytes.
    EXPECT_EQ(meshes.vertices, 4096u * 36);
    EXPECT_EQ(meshes.indices, 4096u * 96);
    EXPECT_EQ(meshes.bytes(), 4096u * 1536);
    ExportOptions options;
    options.memory = {4096 * 1536 - 1};
    refusal([&] { exportPlant(plant, folder / "bush.obj", options); }, "export");
    EXPECT_FALSE(std::filesystem::exists(folder / "bush.obj"));
    options.memory = {4096 * 1536};
    EXPECT_NO_THROW(exportPlant(plant, folder / "bush.obj", options));
    // glTF holds the meshes three times (.glb) and more (.gltf), and a node a joint.
    refusal([&] { exportPlant(plant, folder / "bush.glb", options); }, "export");
    options.memory = {3 * 4096 * 1536 + 4096 * 2048};
    EXPECT_NO_THROW(exportPlant(plant, folder / "bush.glb", options));
    refusal([&] { exportPlant(plant, folder / "bush.gltf", options); }, "export");
    EXPECT_FALSE(std::filesystem::exists(folder / "bush.gltf"));
}

TEST_F(ExportBudget, InstancedExportIsRefusedBeforeWriting) {
    const Grammar bush = loadOk("plants/fractal_bush.lsys");
    BGrammarOptions words;
    words.steps = 4;
    words.interpreted = true;
    const InstanceGraph graph = buildInstanceGraph(buildBGrammar(bush, words), bush);
    GraphExportOptions options;
    options.memory = {4096};
    refusal([&] { exportInstanceGraph(graph, SurfaceLibrary{}, folder / "bush.glb", options); }, "export");
    EXPECT_FALSE(std::filesystem::exists(folder / "bush.glb"));
    options.memory = {64 * kMiB};
    EXPECT_NO_THROW(exportInstanceGraph(graph, SurfaceLibrary{}, folder / "bush.glb", options));
}

} // namespace
} // namespace lsys::test
