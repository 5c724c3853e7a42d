// vlab objects (lsystem/vlab/object.h): finding an object's files from its
// specifications or beside its L-system, and the grammar a loaded object
// gives: the view file's turtle, the colour map's palette, located errors.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

#include "lsystem/language/module_string.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

namespace lsys::vlab {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class VlabObject : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
                  ("plantfield_vlab_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = folder_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    // A colour map whose entry i is (i, 255 - i, 7).
    fs::path writeColorMap(const std::string& name) const {
        std::string bytes;
        for (int i = 0; i < 256; ++i) bytes += {static_cast<char>(i), static_cast<char>(255 - i), 7};
        return write(name, bytes);
    }

    fs::path folder_;
};

constexpr const char* kLsystem = "Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> F+F;F!F\nendlsystem\n";

TEST_F(VlabObject, SpecificationsNameTheFiles) {
    write("plant.l", kLsystem);
    write("other.l", kLsystem);
    write("specifications", "ignore:\n*.swp\n*\nmodel:\n\tgenerate:\n\t\tcpfg -w 300 500 -m colours.map -e env.e "
                            "plant.l view.v anim.a\n\nL-system:\n\tEDIT plant.l\n");
    std::string problem;
    const std::optional<ObjectFiles> files = findObjectFiles(folder_, problem);
    ASSERT_TRUE(files) << problem;
    EXPECT_EQ(files->lsystem, folder_ / "plant.l");
    EXPECT_EQ(files->view, folder_ / "view.v");
    EXPECT_EQ(files->colorMap, folder_ / "colours.map");
    EXPECT_TRUE(files->materials.empty());
    EXPECT_EQ(files->ignored, (std::vector<std::string>{"-e env.e", "anim.a"}));
}

TEST_F(VlabObject, WithoutSpecificationsTheFilesBesideTheLsystem) {
    write("tree.l", kLsystem);
    write("tree.v", "angle increment: 30\n");
    write("other.v", "angle increment: 60\n");
    write("tree.mat", "");
    std::string problem;
    std::optional<ObjectFiles> files = findObjectFiles(folder_, problem);
    ASSERT_TRUE(files) << problem;
    EXPECT_EQ(files->lsystem, folder_ / "tree.l");
    EXPECT_EQ(files->view, folder_ / "tree.v"); // its stem's, among two
    EXPECT_EQ(files->materials, folder_ / "tree.mat");
    EXPECT_TRUE(files->colorMap.empty());
    EXPECT_TRUE(isVlabObject(folder_ / "tree.l"));

    write("second.l", kLsystem);
    files = findObjectFiles(folder_, problem);
    EXPECT_FALSE(files);
    EXPECT_NE(problem.find("second.l, tree.l"), std::string::npos) << problem;
    files = findObjectFiles(folder_ / "second.l", problem); // a .l named: its own files
    ASSERT_TRUE(files);
    EXPECT_EQ(files->lsystem, folder_ / "second.l");
    EXPECT_TRUE(files->view.empty()); // two view files, none of its stem
}

TEST_F(VlabObject, AFolderWithoutLsystemIsAnError) {
    const PlantFile plant = loadObject(folder_);
    ASSERT_EQ(plant.parsed.diagnostics.size(), 1u);
    EXPECT_NE(plant.parsed.diagnostics[0].message.find("holds no cpfg L-system"), std::string::npos);
}

TEST_F(VlabObject, TheViewFileDrivesTheTurtle) {
    write("plant.l", kLsystem);
    write("plant.v", "angle factor: 4\ninitial line width: 3\nline width increment: 1\n"
                     "initial color: 10\ncolor increment: 5\ntropism direction: 0,0,-2\n"
                     "initial elasticity: 0.25\n");
    writeColorMap("plant.map");
    const PlantFile plant = loadObject(folder_);
    ASSERT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    const Grammar& grammar = plant.parsed.grammar;
    EXPECT_DOUBLE_EQ(grammar.angle, 90.0);
    EXPECT_DOUBLE_EQ(grammar.width, 3.0);
    EXPECT_DOUBLE_EQ(grammar.style.widthFactor, 1.0);
    EXPECT_DOUBLE_EQ(grammar.style.widthIncrement, 1.0);
    EXPECT_EQ(grammar.style.colorIncrement, 5);
    EXPECT_EQ(grammar.style.material, 10u);
    EXPECT_EQ(grammar.style.tropism, glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_DOUBLE_EQ(grammar.style.elasticity, 0.25);
    EXPECT_FALSE(grammar.style.pixelLines); // a width without "pixels" is in lengths
    ASSERT_TRUE(grammar.style.look.palette);
    ASSERT_EQ(grammar.style.look.palette->size(), 256u);

    // F+F;F!F: the second F turned 90 degrees, the third in colour 15, the last one 2 wide.
    const PlantAsset drawn = plantFromGrammar(grammar, derive(grammar));
    ASSERT_EQ(drawn.primitives.size(), 4u);
    EXPECT_EQ(drawn.primitives[2].material, 15u);
    EXPECT_FLOAT_EQ(drawn.primitives[3].startRadius, 1.0f);
    EXPECT_EQ(drawn.materials.at(15).albedo, glm::vec3(15.0f / 255.0f, 240.0f / 255.0f, 7.0f / 255.0f));
    EXPECT_EQ(drawn.materials.at(10).albedo, glm::vec3(10.0f / 255.0f, 245.0f / 255.0f, 7.0f / 255.0f));
}

TEST_F(VlabObject, ErrorsInTheObjectsFilesAreLocatedThere) {
    write("plant.l", kLsystem);
    write("plant.v", "angle increment: 30\n\ninitial line width: wide\n");
    const PlantFile plant = loadObject(folder_);
    ASSERT_FALSE(plant.parsed.ok());
    const Diagnostic& error = plant.parsed.diagnostics.front();
    EXPECT_EQ(error.file, (folder_ / "plant.v").string());
    EXPECT_EQ(error.line, 3);
    EXPECT_GT(error.column, 0);
    EXPECT_EQ(error.sourceLine, "initial line width: wide"); // quoted, since it is not the L-system's line
    EXPECT_NE(formatDiagnostics(plant.parsed.diagnostics, plant.source).find("plant.v:3:"), std::string::npos);
}

TEST_F(VlabObject, APlainPlantFileIsNoObject) {
    const fs::path file = write("plant.lsys", "angle: 30\nAxiom: F\n");
    EXPECT_FALSE(isVlabObject(file));
    const PlantFile plant = loadPlant(file);
    ASSERT_TRUE(plant.parsed.ok());
    EXPECT_DOUBLE_EQ(plant.parsed.grammar.angle, 30.0);
    EXPECT_DOUBLE_EQ(plant.parsed.grammar.style.widthFactor, 0.7); // ABOP's turtle
    EXPECT_FALSE(plant.parsed.grammar.style.look.palette);
}

// Two functions cpfg evaluates to 0.25 and 0.75 everywhere, named WIDTH and BEND.
constexpr const char* kFunctionSet = "funcgalleryver 1 1\nitems: 2\n"
                                     "fver 1 1\nname: WIDTH\nsamples: 10\nflip: off\npoints: 4\n"
                                     "0 0.25\n0.3 0.25\n0.6 0.25\n1 0.25\n"
                                     "fver 1 1\nname: BEND\nsamples: 10\nflip: off\npoints: 4\n"
                                     "0 0.75\n0.3 0.75\n0.6 0.75\n1 0.75\n";
// A function file of 0.5 everywhere.
constexpr const char* kHalf = "range: 0 1\npoints: 4\n0 0.5\n0.3 0.5\n0.6 0.5\n1 0.5\n";

// The L-system with `production` for A, derived one step, against `expected`.
void expectDerived(const PlantFile& plant, const std::string& expected) {
    ASSERT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    const Grammar& grammar = plant.parsed.grammar;
    const std::optional<std::string> difference = firstDifference(derive(grammar), grammar.symbols, expected);
    EXPECT_FALSE(difference) << *difference;
}

std::string lsystemWith(const std::string& production) {
    return "Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> " + production + "\nendlsystem\n";
}

// cpfg defines a set's names as macros for the L-system (generate.c,
// PreprocessLsystem); the set drops a function named before it.
TEST_F(VlabObject, AFunctionSetNamesItsFunctionsForTheLsystem) {
    write("plant.l", lsystemWith("B(func(WIDTH, 0.5), func(BEND, 0.1), func(2, 1))"));
    write("plant.v", "function: half.func\nfunction set: shapes.fset\n");
    write("half.func", kHalf);
    write("shapes.fset", kFunctionSet);
    expectDerived(loadObject(folder_), "B(0.25,0.75,0.75)");
    // The tool's own -D wins over a function's name.
    expectDerived(loadObject(folder_, {.defines = {{"BEND", 1.0}}}), "B(0.25,0.25,0.75)");
}

TEST_F(VlabObject, AFunctionLineAfterTheSetAddsItsFunctionButUnnamesTheSet) {
    write("plant.l", "#ifdef WIDTH\n#define NAMED 1\n#else\n#define NAMED 0\n#endif\n" +
                         lsystemWith("B(NAMED, func(1, 0.5), func(3, 0.5))"));
    write("plant.v", "function set: shapes.fset\nfunction: half.func\n");
    write("half.func", kHalf);
    write("shapes.fset", kFunctionSet);
    expectDerived(loadObject(folder_), "B(0,0.25,0.5)");
}

// cpfg's preprocessor rejects -Dleaf-width=1, so the function has only its number.
TEST_F(VlabObject, AFunctionNamedByNoIdentifierIsReadByItsNumber) {
    write("plant.l", lsystemWith("B(func(1, 0.5))"));
    write("plant.v", "\nfunction set: shapes.fset\n");
    write("shapes.fset", "funcgalleryver 1 1\nitems: 1\nfver 1 1\nname: leaf-width\nsamples: 10\nflip: off\n"
                         "points: 4\n0 0.25\n0.3 0.25\n0.6 0.25\n1 0.25\n");
    const PlantFile plant = loadObject(folder_);
    expectDerived(plant, "B(0.25)");
    ASSERT_EQ(plant.parsed.warnings.size(), 1u);
    EXPECT_EQ(plant.parsed.warnings[0].line, 2);
    EXPECT_NE(plant.parsed.warnings[0].message.find("'leaf-width' (func(1, x))"), std::string::npos)
        << plant.parsed.warnings[0].message;
}

// cpfg skips a surface file that is not there and reads a function file it
// cannot open as 0; plantfield warns of both at the view file's line.
TEST_F(VlabObject, MissingFilesOfTheViewAreWarnedOfAndDrawNothing) {
    write("plant.l", lsystemWith("F~l(2)FB(func(1, 0.5), func(2, 0.5))"));
    write("plant.v", "function set: lost.fset\nsurface: l nowhere.s 1\n\nfunction: gone.func\nfunction: half.func\n");
    write("half.func", kHalf);
    const PlantFile plant = loadObject(folder_);
    expectDerived(plant, "F~l(2)FB(0,0.5)");
    const std::vector<Diagnostic>& warnings = plant.parsed.warnings;
    ASSERT_EQ(warnings.size(), 3u);
    auto warningOf = [&](const std::string& file) { // the one naming the file, else none
        for (const Diagnostic& warning : warnings)
            if (warning.message.find("'" + file + "'") != std::string::npos) return warning;
        return Diagnostic{};
    };
    const std::pair<const char*, int> expected[] = {{"lost.fset", 1}, {"nowhere.s", 2}, {"gone.func", 4}};
    for (const auto& [file, line] : expected) {
        const Diagnostic& warning = warningOf(file);
        EXPECT_EQ(std::tie(warning.file, warning.line, warning.severity),
                  std::tuple((folder_ / "plant.v").string(), line, Severity::Warning));
    }
    EXPECT_NE(warningOf("nowhere.s").message.find("~l draws nothing"), std::string::npos);
    EXPECT_EQ(warningOf("gone.func").sourceLine, "function: gone.func"); // quoted: not the L-system's line

    // ~l leaves the turtle where it is, as cpfg's determine_end_point does for an id without a surface.
    const Grammar& grammar = plant.parsed.grammar;
    const PlantAsset drawn = plantFromGrammar(grammar, derive(grammar));
    ASSERT_EQ(drawn.primitives.size(), 3u);
    EXPECT_EQ(drawn.primitives[1].kind, PrimitiveKind::Surface);
    EXPECT_TRUE(drawn.surfaces.at(drawn.primitives[1].shape).positions.empty());
    EXPECT_NEAR(glm::length(drawn.primitives[2].frame.position - drawn.primitives[0].frame.position), 1.0f, 1e-6f);
}

// Each sample a function is prepared with is a bisection: an object's
// function files share one bound on them, as a set's functions do, so 300
// files of 60000 samples each (about a minute apiece before) are refused at
// the first file past it, at its view file's samples, quickly.
TEST_F(VlabObject, AnObjectsFunctionFilesShareTheBoundOnSamples) {
    write("plant.l", lsystemWith("B(func(1, 0.5))"));
    std::string view;
    for (int i = 0; i < 300; ++i) {
        const std::string name = "f" + std::to_string(i) + ".func";
        write(name, kHalf);
        view += "function: " + name + " 60000\n";
    }
    write("plant.v", view);
    const PlantFile plant = loadObject(folder_);
    const std::vector<Diagnostic>& errors = plant.parsed.diagnostics;
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].file, (folder_ / "f1.func").string());
    EXPECT_NE(errors[0].message.find("asks for 60000 samples, too many"), std::string::npos) << errors[0].message;
    EXPECT_EQ(errors.size(), 299u); // every file after the first
}

} // namespace
} // namespace lsys::vlab
