// cpfg's view file (.v) is read as cpfg's interpret.c (ReadViewData) reads
// it: its labels, its defaults, the quirks of its scanning, and diagnostics
// at the line and column of what is wrong.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <tuple>

#include "lsystem/vlab/view_file.h"

namespace lsys::vlab {
namespace {

// A fresh folder for one test's files, removed afterwards.
struct Folder {
    std::filesystem::path path;
    Folder()
        : path(std::filesystem::temp_directory_path() /
               ("plantfield_view_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~Folder() { std::filesystem::remove_all(path); }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name, std::ios::binary) << text;
        return path / name;
    }
};

ViewFile parsedOk(const std::string& text) {
    const ViewReadResult result = parseViewFile(text, "plant.v");
    EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    EXPECT_TRUE(result.warnings.empty()) << (result.warnings.empty() ? "" : result.warnings[0].message);
    return result.view;
}

void expectAt(const Diagnostic& diagnostic, int line, int column) {
    EXPECT_EQ(diagnostic.line, line) << diagnostic.message;
    EXPECT_EQ(diagnostic.column, column) << diagnostic.message;
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << "component " << i;
}

TEST(ViewFile, DefaultsAreCpfgsWhereLabelsAreAbsent) {
    // cpfg's interpret.c, InitializeParameters.
    const ViewFile view = parsedOk("/* nothing but a comment */\n\n");
    EXPECT_EQ(view.angleIncrement, 45.0f);
    EXPECT_EQ(view.initialColor, 128);
    EXPECT_FALSE(view.initialBackColor.has_value());
    EXPECT_EQ(view.colorIncrement, 1);
    EXPECT_FALSE(view.backColorIncrement.has_value());
    EXPECT_EQ(view.initialLineWidth, 1.0f);
    EXPECT_EQ(view.lineStyle, LineStyle::Pixel);
    EXPECT_EQ(view.lineWidthIncrement, 0.0f);
    EXPECT_TRUE(view.taperedLines);
    EXPECT_EQ(view.contourSides, 8);
    expectNear(view.tropismDirection, {0, 1, 0});
    EXPECT_EQ(view.initialElasticity, 0.0f);
    EXPECT_EQ(view.elasticityIncrement, 0.0f);
    EXPECT_EQ(view.initialScale, 1.0f);
    EXPECT_EQ(view.scaleMultiplier, 1.0f);
    expectNear(view.viewpoint, {0, 0, 1});
    expectNear(view.viewReferencePoint, {0, 0, 0});
    EXPECT_EQ(view.twist, 0.0f);
    EXPECT_FALSE(view.perspective);
    EXPECT_EQ(view.viewingAngle, 45.0f);
    EXPECT_EQ(view.zoom, 1.0f);
    EXPECT_FALSE(view.box.has_value());
    expectNear(view.lightDirection, {1, 0, 0});
    EXPECT_TRUE(view.surfaces.empty() && view.functions.empty() && view.contours.empty());
}

TEST(ViewFile, AngleFactorDividesAFullTurn) {
    EXPECT_FLOAT_EQ(parsedOk("angle factor: 8\n").angleIncrement, 45.0f);
    EXPECT_FLOAT_EQ(parsedOk("angle factor: 6\n").angleIncrement, 60.0f);
    EXPECT_FLOAT_EQ(parsedOk("angle factor: 12\nangle increment: 22.5\n").angleIncrement, 22.5f);
    EXPECT_FLOAT_EQ(parsedOk("angle increment: 30\nangle factor: 4\n").angleIncrement, 90.0f);
}

TEST(ViewFile, InitialLineWidthChoosesPixelsPolygonsOrCylinders) {
    ViewFile view = parsedOk("initial line width: 2 pixels\n");
    EXPECT_EQ(view.initialLineWidth, 2.0f);
    EXPECT_EQ(view.lineStyle, LineStyle::Pixel);
    view = parsedOk("initial line width: 0.5\n");
    EXPECT_EQ(view.initialLineWidth, 0.5f);
    EXPECT_EQ(view.lineStyle, LineStyle::Polygon);
    EXPECT_EQ(parsedOk("initial line width: 3 p\n").lineStyle, LineStyle::Pixel);
    EXPECT_EQ(parsedOk("initial line width: 3 solid\n").lineStyle, LineStyle::Cylinder);
    // cpfg reads only the word's first letter: "cylinder" leaves polygons.
    const ViewReadResult result = parseViewFile("initial line width: 2 cylinder\n", "plant.v");
    EXPECT_TRUE(result.ok());
    EXPECT_EQ(result.view.lineStyle, LineStyle::Polygon);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0].column, 23);
    // "line style:" after it decides.
    EXPECT_EQ(parsedOk("initial line width: 2 pixels\nline style: cylinder\n").lineStyle, LineStyle::Cylinder);
}

TEST(ViewFile, LineStyleNamesAStyle) {
    EXPECT_EQ(parsedOk("line style: pixel\n").lineStyle, LineStyle::Pixel);
    EXPECT_EQ(parsedOk("line style: polygon\n").lineStyle, LineStyle::Polygon);
    EXPECT_EQ(parsedOk("line style: cylinder\n").lineStyle, LineStyle::Cylinder);
    EXPECT_EQ(parsedOk("line style: 3\n").lineStyle, LineStyle::Cylinder); // cpfg's '1' is the first
    const ViewReadResult unknown = parseViewFile("line style: polygon\nline style: tube\n", "plant.v");
    EXPECT_EQ(unknown.view.lineStyle, LineStyle::Polygon); // the style stays
    ASSERT_EQ(unknown.warnings.size(), 1u);
    EXPECT_EQ(unknown.warnings[0].line, 2);
    EXPECT_NE(unknown.warnings[0].message.find("tube"), std::string::npos);
}

TEST(ViewFile, TurtleLabelsAreRead) {
    const ViewFile view = parsedOk("initial color: 3 7\ncolor increment: 2 5\nline width increment: 0.25\n"
                                   "tapered lines: off\ncontour sides: 12\ntropism direction: 0.0,-2.0,0\n"
                                   "initial elasticity: 0.1\nelasticity increment: -0.05\ninitial scale: 2\n"
                                   "scale multiplier: 0.9\n");
    EXPECT_EQ(view.initialColor, 3);
    EXPECT_EQ(view.initialBackColor, 7);
    EXPECT_EQ(view.colorIncrement, 2);
    EXPECT_EQ(view.backColorIncrement, 5);
    EXPECT_EQ(view.lineWidthIncrement, 0.25f);
    EXPECT_FALSE(view.taperedLines);
    EXPECT_EQ(view.contourSides, 12);
    expectNear(view.tropismDirection, {0, -1, 0}); // normalised, as cpfg divides by the length
    EXPECT_FLOAT_EQ(view.initialElasticity, 0.1f);
    EXPECT_FLOAT_EQ(view.elasticityIncrement, -0.05f);
    EXPECT_EQ(view.initialScale, 2.0f);
    EXPECT_FLOAT_EQ(view.scaleMultiplier, 0.9f);
    // The front colour alone; cpfg's corrections of sides and scales.
    const ViewFile corrected = parsedOk("initial color: 4\ncontour sides: 2\ninitial scale: 0\nscale multiplier: 0\n");
    EXPECT_EQ(corrected.initialColor, 4);
    EXPECT_FALSE(corrected.initialBackColor.has_value());
    EXPECT_EQ(corrected.contourSides, 3);
    EXPECT_EQ(corrected.initialScale, 1.0f);
    EXPECT_EQ(corrected.scaleMultiplier, 1.0f);
    // "polygonization level: n", the older label: 2^(n+1) sides.
    EXPECT_EQ(parsedOk("polygonization level: 3\n").contourSides, 16);
    EXPECT_EQ(parsedOk("polygonization level: 0\n").contourSides, 3);
}

TEST(ViewFile, CameraLabelsAreRead) {
    const ViewFile view = parsedOk("viewpoint: 4,-5,30\nview reference point: 0, 1.5, 0\ntwist: 15\n"
                                   "projection: perspective\nviewing angle: 30\nscale factor: 0.9\n"
                                   "box: x: -1,1 y: 0,2 z: -3,3\nlight direction: 2.0,0,0\n");
    expectNear(view.viewpoint, {4, -5, 30});
    expectNear(view.viewReferencePoint, {0, 1.5f, 0});
    EXPECT_EQ(view.twist, 15.0f);
    EXPECT_TRUE(view.perspective);
    EXPECT_EQ(view.viewingAngle, 30.0f);
    EXPECT_FLOAT_EQ(view.zoom, 0.9f);
    ASSERT_TRUE(view.box.has_value());
    expectNear(view.box->min, {-1, 0, -3});
    expectNear(view.box->max, {1, 2, 3});
    expectNear(view.lightDirection, {1, 0, 0});
    EXPECT_FALSE(parsedOk("projection: perspective\nprojection: parallel\n").perspective);
    EXPECT_EQ(parsedOk("scale factor: 0\n").zoom, 1.0f); // cpfg: 0 is 1
    const ViewReadResult odd = parseViewFile("projection: orthographic\n", "plant.v");
    EXPECT_FALSE(odd.view.perspective); // cpfg: "Parallel assumed"
    ASSERT_EQ(odd.warnings.size(), 1u);
    EXPECT_EQ(odd.warnings[0].column, 13);
}

TEST(ViewFile, SurfacesFunctionsAndContoursAreListedInOrder) {
    const ViewFile view = parsedOk("surface: l leaf.s 1 8 4\nsurface: p petal.s 2.75\nsurface: t tex.s 1.5 2\n"
                                   "surface: b bud.s 0 3 3 1\nfunction: internode.func 100\nfunction: rho.func\n"
                                   "contour: 1 leaf.con\ncontour: 2 stripe.con\n");
    using namespace std::string_literals;
    auto surface = [&](size_t i) {
        const ViewSurface& s = view.surfaces.at(i);
        return std::tuple(s.id, s.file, s.scale, s.sPrecision, s.tPrecision, s.texture, s.line);
    };
    ASSERT_EQ(view.surfaces.size(), 4u);
    EXPECT_EQ(surface(0), std::tuple("l"s, "leaf.s"s, 1.0f, 8, 4, -1, 1));
    EXPECT_EQ(surface(1), std::tuple("p"s, "petal.s"s, 2.75f, 0, 0, -1, 2));
    EXPECT_EQ(surface(2), std::tuple("t"s, "tex.s"s, 1.5f, 0, 0, 2, 3)); // one number after the scale: the texture
    EXPECT_EQ(surface(3), std::tuple("b"s, "bud.s"s, 1.0f, 3, 3, 1, 4)); // a scale not positive is 1
    ASSERT_EQ(view.functions.size(), 2u);
    EXPECT_EQ(std::tie(view.functions[0].file, view.functions[0].samples), std::tuple("internode.func"s, 100));
    EXPECT_EQ(std::tie(view.functions[1].file, view.functions[1].samples, view.functions[1].line),
              std::tuple("rho.func"s, -1, 6));
    ASSERT_EQ(view.contours.size(), 2u);
    EXPECT_EQ(std::tie(view.contours[1].id, view.contours[1].file, view.contours[1].line),
              std::tuple(2, "stripe.con"s, 8));
}

// cpfg's ReadFunctionSet empties the table of functions, and a "function:"
// line after the set adds to it but stops cpfg naming the set's functions.
TEST(ViewFile, AFunctionSetReplacesTheFunctionsBeforeIt) {
    using namespace std::string_literals;
    const ViewFile named = parsedOk("function: a.func\nfunction set: shapes.fset\n");
    ASSERT_TRUE(named.functionSet);
    EXPECT_EQ(std::tie(named.functionSet->file, named.functionSet->line, named.functionSet->names),
              std::tuple("shapes.fset"s, 2, true));
    EXPECT_TRUE(named.functions.empty());

    const ViewFile unnamed = parsedOk("function set: shapes.fset\nfunction: b.func 20\n");
    ASSERT_TRUE(unnamed.functionSet);
    EXPECT_FALSE(unnamed.functionSet->names);
    ASSERT_EQ(unnamed.functions.size(), 1u);
    EXPECT_EQ(unnamed.functions[0].file, "b.func");
}

TEST(ViewFile, SurfaceIdIsOneCharacterAsCpfgReadsIt) {
    const ViewReadResult result = parseViewFile("surface: leaf.s 1 6 12\n", "plant.v");
    EXPECT_TRUE(result.ok());
    ASSERT_EQ(result.view.surfaces.size(), 1u);
    EXPECT_EQ(result.view.surfaces[0].id, "l");
    EXPECT_EQ(result.view.surfaces[0].file, "eaf.s");
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0].column, 10);
}

TEST(ViewFile, LabelsNotDrawnAreNamedInWarningsAtTheirPosition) {
    const ViewReadResult result =
        parseViewFile("angle factor: 8\n  texture: F: leaf.png E: m R: 1.6\n"
                      "blob: field.dat 1 1 1\ntsurface: s leaf.t 1\ncurve: profile.con\n"
                      "background scene: background.dat\nline: L line.s .01\nangle increment: 30\n",
                      "plant.v");
    EXPECT_TRUE(result.ok());
    EXPECT_EQ(result.view.angleIncrement, 30.0f); // what follows their values is read on
    const char* labels[] = {"texture:", "blob:", "tsurface:", "curve:", "background scene:", "line:"};
    ASSERT_EQ(result.warnings.size(), std::size(labels));
    for (size_t i = 0; i < std::size(labels); ++i) {
        EXPECT_EQ(result.warnings[i].severity, Severity::Warning);
        EXPECT_EQ(result.warnings[i].file, "plant.v");
        expectAt(result.warnings[i], int(i) + 2, i == 0 ? 3 : 1);
        EXPECT_NE(result.warnings[i].message.find(labels[i]), std::string::npos) << result.warnings[i].message;
    }
}

// cpfg's movements (movements.c, read_movement): letters and values split
// as strtok splits them, the direction normalised and scaled by the
// intensity (kept within [-1, 1]), tropisms and torques in one list.
TEST(ViewFile, TropismAndTorqueLinesAreMovementsInFileOrder) {
    const ViewFile view = parsedOk("tropism: T: 0,-2,0 E: 0.2\ntorque: T: 0.0 0.0 1.0  E:0.5\n"
                                   "tropism:  T: 3 0 4 I: 0.5 A:90 E: 0.1 S: 0.05\nangle increment: 30\n");
    ASSERT_EQ(view.movements.size(), 3u);
    EXPECT_EQ(view.movements[0].kind, MovementKind::Tropism);
    expectNear(view.movements[0].direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(view.movements[0].elasticity, 0.2f);
    EXPECT_EQ(view.movements[1].kind, MovementKind::Twist);
    EXPECT_FLOAT_EQ(view.movements[1].elasticity, 0.5f);
    expectNear(view.movements[2].direction, {0.3f, 0, 0.4f}); // (3, 0, 4) / 5 x 0.5
    EXPECT_FLOAT_EQ(view.movements[2].angle, 90.0f);
    EXPECT_FLOAT_EQ(view.movements[2].increment, 0.05f);
    EXPECT_EQ(view.angleIncrement, 30.0f); // the line after is read on
}

// What cpfg ignores (with a message) is ignored with a warning at the
// letter; a number missing after a letter, where cpfg's atof(NULL) would
// crash, is an error at the line's end.
TEST(ViewFile, MovementsCpfgIgnoresAreWarnedOfAndAMissingNumberIsAnError) {
    const ViewReadResult ignored =
        parseViewFile("tropism: T: 0,0,0 E: 1\ntropism: I: 0.5 T: 0,1,0\ntorque: T: 0,1,0 Q: 2\n", "plant.v");
    EXPECT_TRUE(ignored.ok());
    EXPECT_TRUE(ignored.view.movements.empty());
    ASSERT_EQ(ignored.warnings.size(), 3u);
    expectAt(ignored.warnings[0], 1, 10);
    EXPECT_NE(ignored.warnings[0].message.find("a zero direction"), std::string::npos);
    expectAt(ignored.warnings[1], 2, 10);
    expectAt(ignored.warnings[2], 3, 18);
    EXPECT_NE(ignored.warnings[2].message.find("unknown letter 'Q'"), std::string::npos) << ignored.warnings[2].message;

    std::string eleven;
    for (int i = 0; i < 11; ++i) eleven += "tropism: T: 0,1,0\n";
    const ViewReadResult many = parseViewFile(eleven, "plant.v");
    EXPECT_EQ(many.view.movements.size(), kMaxMovements);
    ASSERT_EQ(many.warnings.size(), 1u);
    EXPECT_EQ(many.warnings[0].line, 11);

    const ViewReadResult missing = parseViewFile("tropism: T: 0,1\n", "plant.v");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.diagnostics[0].message.find("a number is missing"), std::string::npos);
    EXPECT_EQ(missing.diagnostics[0].line, 1);
}

TEST(ViewFile, LabelsOfCpfgsWindowAreAcceptedQuietly) {
    // Every other label of cpfg's table, with values from vlab's examples.
    parsedOk("front distance: -100\nback distance: 100.0\nz buffer: on\ncue range: 0\nshade mode: 3\n"
             "diffuse reflection: 16\nsurface ambient: 0.15\nsurface diffuse: 0.75\nbackground color: 0,0,0\n"
             "ambient light: 0.1,0.1,0.1\nfont:  -*-courier-*-r-*-*-26-*-*-*-*-*-*-*\n"
             "light: V: -0.5,-1.0,-2.0 A: 0.6 0.6 0.6 D 0.6 0.6 0.6 S: 0.6 0.6 0.6\nrender mode: shaded\n"
             "twist of cylinders: on\ninterpretation step: 2\ninterpretation past %: off\n"
             "rayshade objects: leaf.ray\nrayshade scale: 1\nenvironment display: before\nantialiasing: on\n"
             "min zoom: 0.1\nmax zoom: 10\ngenerate on view change: off\nwinfont: \"Arial\" 12 B\n"
             "concave polygons: on\nshadow map: size: 4096\nPS linecap: 1\n");
}

TEST(ViewFile, UnknownLabelsWarnAndTheirLineIsSkipped) {
    const ViewReadResult result =
        parseViewFile("colour increment: 3\nangle factor: 4\ntwist: 22.5\n\tangle increment: 10\n", "plant.v");
    EXPECT_TRUE(result.ok());
    EXPECT_FLOAT_EQ(result.view.angleIncrement, 90.0f);
    EXPECT_EQ(result.view.twist, 22.0f); // " %d" reads 22; ".5" is read as the next label, as in cpfg
    ASSERT_EQ(result.warnings.size(), 3u);
    expectAt(result.warnings[0], 1, 1);
    EXPECT_NE(result.warnings[0].message.find("colour increment:"), std::string::npos);
    expectAt(result.warnings[1], 3, 10);
    EXPECT_EQ(result.warnings[2].line, 4); // cpfg matches labels exactly: a tab is no space
}

TEST(ViewFile, MalformedValuesAreErrorsAtTheirColumn) {
    struct Case {
        const char* text;
        int line, column;
    };
    // Values stay on their label's line: "angle increment:" alone is an error.
    const Case cases[] = {{"angle increment: abc\n", 1, 18}, {"angle factor: 8\nangle factor: 0\n", 2, 15},
                          {"viewpoint: 0 ,0,1\n", 1, 14},    {"tropism direction: 0,0,0\n", 1, 20},
                          {"surface: l leaf.s\n", 1, 18},    {"contour: leaf.con\n", 1, 10},
                          {"initial color: red\n", 1, 16},   {"box: x: -1,1 y: 0,2\n", 1, 20},
                          {"angle increment:\n30\n", 1, 17}, {"polygonization level: 40\n", 1, 23},
                          {"contour sides: -\n", 1, 16},     {"function:\n", 1, 10}};
    for (const Case& c : cases) {
        const ViewReadResult result = parseViewFile(c.text, "plant.v");
        ASSERT_EQ(result.diagnostics.size(), 1u) << c.text;
        const Diagnostic& error = result.diagnostics[0];
        EXPECT_EQ(error.severity, Severity::Error) << c.text;
        EXPECT_EQ(error.file, "plant.v");
        expectAt(error, c.line, c.column);
        EXPECT_FALSE(error.expected.empty()) << c.text;
    }
    const ViewReadResult result = parseViewFile("angle increment: abc\nangle factor: 8\n", "plant.v");
    EXPECT_NE(result.diagnostics[0].message.find("angle increment:"), std::string::npos);
    EXPECT_NE(result.diagnostics[0].expected.find("a number"), std::string::npos);
    EXPECT_EQ(result.view.angleIncrement, 45.0f); // the next line is read on
}

TEST(ViewFile, CommentsAreSkippedAndKeepLinesAndColumns) {
    const ViewReadResult result = parseViewFile("/* angle factor: 3 */\nangle increment: /* inline */ 30 // C++\n"
                                                "/* two\n   lines */ initial color: 5\ntwist: x\n",
                                                "plant.v");
    EXPECT_EQ(result.view.angleIncrement, 30.0f);
    EXPECT_EQ(result.view.initialColor, 5);
    EXPECT_TRUE(result.warnings.empty());
    ASSERT_EQ(result.diagnostics.size(), 1u);
    expectAt(result.diagnostics[0], 5, 8);
}

TEST(ViewFile, LineMarkersOfThePreprocessorPlaceDiagnostics) {
    const ViewReadResult result = parseViewFile("# 1 \"plant.v\"\nangle factor: 8\n# 10 \"common.h\" 1\n"
                                                "texture: bark.png\n#line 3 \"plant.v\"\ntwist: x\n",
                                                "<stdin>");
    EXPECT_EQ(result.view.angleIncrement, 45.0f);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0].file, "common.h");
    EXPECT_EQ(result.warnings[0].line, 10);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].file, "plant.v");
    EXPECT_EQ(result.diagnostics[0].line, 3);
    EXPECT_FALSE(parseViewFile("#define N 3\n", "plant.v").ok()); // no marker: run the preprocessor first
}

TEST(ViewFile, GarbageNeverCrashesAndIsReported) {
    EXPECT_FALSE(parseViewFile(std::string("angle factor: 8\n\0\x01\xff:", 20), "plant.v").ok());
    const std::string longLine(1 << 20, 'x');
    EXPECT_FALSE(parseViewFile(longLine, "plant.v").warnings.empty());
    EXPECT_FALSE(parseViewFile("angle increment: " + longLine, "plant.v").ok());
    const ViewReadResult colons = parseViewFile(std::string(200000, ':'), "plant.v");
    EXPECT_LE(colons.warnings.size(), 1001u); // kept short
    std::mt19937 random(7);
    // Pieces of view files, '|' between them, and a NUL byte.
    const std::string_view text = "angle factor:|surface:|box:| x:|#|/*|*/|//|\n|\t|,|1|-2.5e3|a|\"|%|\xff|1e99";
    std::vector<std::string> pieces{std::string(1, '\0')};
    for (size_t at = 0, end = 0; at <= text.size(); at = end + 1) {
        end = std::min(text.find('|', at), text.size());
        pieces.emplace_back(text.substr(at, end - at));
    }
    for (int round = 0; round < 2000; ++round) {
        std::string fuzz;
        for (int i = 0, n = int(random() % 40); i < n; ++i) fuzz += pieces[random() % pieces.size()];
        const ViewReadResult result = parseViewFile(fuzz, "fuzz.v");
        for (const Diagnostic& d : result.diagnostics) EXPECT_GE(d.column, 1) << fuzz;
    }
}

// vlab's Lilac (oofs/ext/10-manuals/ext/11-CPFG/ext/Lilac/plant.v), verbatim.
constexpr const char* kLilac = "angle factor: 12 \n"
                               "initial color: 3\n"
                               "initial line width: 0.1 \n"
                               "line width increment: 0.1\n"
                               "viewpoint: 4,-5,30\n"
                               "view reference point: 0,0,0\n"
                               "twist: 0\n"
                               "projection: parallel\n"
                               "front distance: -1000.0\n"
                               "back distance: 1000.0\n"
                               "scale factor: 0.90\n"
                               "z buffer: on\n"
                               "render mode: shadows\n"
                               "line style: cylinder\n"
                               "light direction: 2.0,1.3,1.5\n"
                               "tropism direction: 0.0,-2.0,0\n"
                               "surface: p petal.s 2.75\n"
                               "surface: c calyx.s 2.0\n"
                               "function: br_ang.func 100\n"
                               "function: elas.func 100\n"
                               "\n"
                               "shadow map: size: 4096\n";

TEST(ViewFile, VlabsLilacViewFileIsRead) {
    const ViewFile view = parsedOk(kLilac);
    EXPECT_FLOAT_EQ(view.angleIncrement, 30.0f);
    EXPECT_EQ(view.initialColor, 3);
    EXPECT_FLOAT_EQ(view.initialLineWidth, 0.1f);
    EXPECT_FLOAT_EQ(view.lineWidthIncrement, 0.1f);
    EXPECT_EQ(view.lineStyle, LineStyle::Cylinder);
    expectNear(view.viewpoint, {4, -5, 30});
    EXPECT_FLOAT_EQ(view.zoom, 0.9f);
    expectNear(view.lightDirection, glm::vec3(2.0f, 1.3f, 1.5f) / std::sqrt(4.0f + 1.69f + 2.25f));
    expectNear(view.tropismDirection, {0, -1, 0});
    ASSERT_EQ(view.surfaces.size(), 2u);
    EXPECT_EQ(view.surfaces[1].id, "c");
    EXPECT_EQ(view.surfaces[1].file, "calyx.s");
    EXPECT_EQ(view.surfaces[1].scale, 2.0f);
    ASSERT_EQ(view.functions.size(), 2u);
    EXPECT_EQ(view.functions[1].file, "elas.func");
}

TEST(ViewFile, ReadViewFileRunsThePreprocessorAndPointsIntoIncludedFiles) {
    const Folder folder;
    folder.write("common.v", "texture: bark.png\nangle increment: zz\n");
    const std::filesystem::path plant =
        folder.write("plant.v", "#define STEPS 8\n/* a comment */\nangle factor: STEPS\n#include \"common.v\"\n");
    const ViewReadResult result = readViewFile(plant);
    EXPECT_EQ(result.view.angleIncrement, 45.0f);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0].line, 1);
    EXPECT_NE(result.warnings[0].file.find("common.v"), std::string::npos);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    expectAt(result.diagnostics[0], 2, 18);
    EXPECT_NE(result.diagnostics[0].file.find("common.v"), std::string::npos);

    const ViewReadResult lilac = readViewFile(folder.write("lilac.v", kLilac));
    EXPECT_TRUE(lilac.ok());
    ASSERT_EQ(lilac.view.functions.size(), 2u);
    EXPECT_EQ(lilac.view.functions[0].line, 19);
}

TEST(ViewFile, UnreadableFilesAreNamed) {
    const Folder folder;
    const std::filesystem::path missing = folder.path / "missing.v";
    const ViewReadResult result = readViewFile(missing);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_NE(result.diagnostics[0].message.find(missing.string()), std::string::npos);
    EXPECT_FALSE(readViewFile(folder.path).ok());
    const std::string elf("\177ELF\0\0\2:", 8);
    EXPECT_FALSE(readViewFile(folder.write("binary.v", elf)).ok());
}

} // namespace
} // namespace lsys::vlab
