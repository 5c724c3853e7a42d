// vlab's function files (.func) and function sets (.fset), read and
// evaluated as cpfg's splinefun.cpp does. The expected values are cpfg's own:
// cpfg 6.6 run headless (/work/cpfg/cpfg-str.sh) on an L-system whose
// productions write func(id, x) into module parameters, its string printed
// with %g (6 significant digits), hence the tolerance.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "lsystem/vlab/function_file.h"

namespace lsys::vlab {
namespace {

// Half a unit in the 6th significant digit, and float rounding.
double cpfgTolerance(double value) { return 6e-6 * std::fabs(value) + 1e-9; }

// A function file in a fresh temporary folder, removed with it.
struct TempFunction {
    std::filesystem::path folder;
    std::filesystem::path path;
    TempFunction(const std::string& name, const std::string& text)
        : folder(std::filesystem::temp_directory_path() /
                 ("plantfield_func_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()))),
          path(folder / name) {
        std::filesystem::create_directories(folder);
        std::ofstream(path, std::ios::binary) << text;
    }
    ~TempFunction() { std::filesystem::remove_all(folder); }
};

// FernLeaf's brangle.func (vlab's 15-VlabTools examples): the older format.
const char* const kRangeFormat = "range: 0.000000 1.000000\n"
                                 "points: 4\n"
                                 "0.000000 1.100946\n"
                                 "0.218100 0.872272\n"
                                 "0.328571 0.817075\n"
                                 "1.000000 0.485892\n";

// FernLeaf's curvature.func: funcedit's format, with 10 samples of its own.
const char* const kFverFormat = "fver 1 1\n"
                                "name: curvature\n"
                                "samples: 10\n"
                                "flip: off\n"
                                "points: 6\n"
                                "0.000000 0.113486 1\n"
                                "0.283200 0.348686 1\n"
                                "0.417600 -0.020914 1\n"
                                "0.484800 -0.020914 1\n"
                                "0.780952 -0.555200 1\n"
                                "1.000000 -0.630514 1\n";

// funcedit's optional lines (a background image, markers) and repeated
// points (the third column), without samples: cpfg then evaluates by bisection.
const char* const kEditorLines = "fver 1 1\n"
                                 "name: twisty\n"
                                 "samples: 0\n"
                                 "background: image.png\n"
                                 "backgroundXY: 0.000000 0.000000\n"
                                 "markers: 2\n"
                                 "m1 0.2 0.3\n"
                                 "m2 0.5 0.5\n"
                                 "flip: off\n"
                                 "points: 6\n"
                                 "0.000000 0.1 1\n"
                                 "0.15 0.9 2\n"
                                 "0.4 -0.3 1\n"
                                 "0.6 0.5 1\n"
                                 "0.85 1.2 3\n"
                                 "1.000000 0.2 1\n";

// The x values func was called with; beyond [0, 1] cpfg clamps.
const std::vector<double> kXs = {0, 0.05, 0.1, 0.17, 0.25, 0.333, 0.5, 0.61, 0.75, 0.9, 0.99, 1, 1.5, -0.5};

void expectCpfgValues(const VlabFunction& function, const std::vector<double>& cpfg) {
    ASSERT_EQ(cpfg.size(), kXs.size());
    for (size_t i = 0; i < kXs.size(); ++i)
        EXPECT_NEAR(evaluateFunction(function, kXs[i]), cpfg[i], cpfgTolerance(cpfg[i])) << "x = " << kXs[i];
}

FunctionReadResult readOk(const std::string& name, const std::string& text, int samples) {
    TempFunction file(name, text);
    FunctionReadResult result = readFunctionFile(file.path, samples);
    EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    return result;
}

TEST(FunctionFile, RangeFormatIsSampledAsTheViewFileSays) {
    const FunctionReadResult read = readOk("brangle.func", kRangeFormat, 100);
    EXPECT_EQ(read.function.name, "brangle"); // no name line: the file's
    EXPECT_EQ(read.function.samples.size(), 100u);
    expectCpfgValues(read.function, {1.10028, 1.04966, 1.0014, 0.942462, 0.88322, 0.830088, 0.736879, 0.679637,
                                     0.609328, 0.535514, 0.49068, 0.486377, 0.486377, 1.10028});
}

TEST(FunctionFile, WithoutSamplesTheCurveIsSearchedByBisection) {
    const FunctionReadResult read = readOk("brangle.func", kRangeFormat, -1);
    EXPECT_TRUE(read.function.samples.empty());
    // Within 0.001 of x, as cpfg searches: these differ from the sampled values above.
    expectCpfgValues(read.function, {1.10028, 1.05031, 1.00258, 0.941125, 0.882747, 0.829894, 0.736888, 0.680386,
                                     0.609717, 0.53516, 0.490724, 0.486377, 0.486377, 1.10028});
}

TEST(FunctionFile, FverFormatKeepsItsOwnSamples) {
    const FunctionReadResult read = readOk("c.func", kFverFormat, 100); // cpfg ignores the view's 100 here
    EXPECT_EQ(read.function.name, "curvature");
    EXPECT_EQ(read.function.samples.size(), 10u);
    expectCpfgValues(read.function, {0.114002, 0.14884, 0.183678, 0.210738, 0.215581, 0.178863, -0.0881319, -0.2509,
                                     -0.441804, -0.57927, -0.625091, -0.630182, -0.630182, 0.114002});
}

TEST(FunctionFile, EditorLinesAreSkippedAndRepeatedPointsCount) {
    const FunctionReadResult read = readOk("t.func", kEditorLines, 100);
    EXPECT_EQ(read.function.name, "twisty");
    EXPECT_EQ(read.function.xs.size(), 9u); // 6 points, one twice and one three times
    EXPECT_TRUE(read.function.samples.empty());
    expectCpfgValues(read.function, {0.10351, 0.37078, 0.625419, 0.792091, 0.431639, 0.139853, 0.137491, 0.492115,
                                     0.919186, 0.863845, 0.268677, 0.204388, 0.204388, 0.10351});
    EXPECT_TRUE(std::isnan(evaluateFunction(read.function, NAN)));
}

// cpfg ("function set: s.fset" in the view file) gave func(1, x) and func(2, x).
TEST(FunctionFile, FunctionSetHoldsItsFunctionsInOrder) {
    TempFunction file("s.fset", std::string("funcgalleryver 1 1\nitems: 2\n") +
                                    "fver 1 1\nname: WIDTH\nsamples: 10\nflip: off\npoints: 4\n0.000000 1.013734 1\n"
                                    "0.230453 0.561893 1\n0.778895 0.452828 1\n1.000000 0.209768 1\n" +
                                    kRangeFormat);
    const FunctionSetReadResult read = readFunctionSet(file.path);
    ASSERT_TRUE(read.ok()) << read.diagnostics[0].message;
    ASSERT_EQ(read.functions.size(), 2u);
    EXPECT_EQ(read.functions[0].name, "WIDTH");
    EXPECT_EQ(read.functions[1].samples.size(), 100u); // a set prepares the older format with 100
    const double xs[] = {0, 0.3, 0.77, 1};
    const double cpfg[2][4] = {{1.01241, 0.669997, 0.382402, 0.21048}, {1.10028, 0.850418, 0.599903, 0.486377}};
    for (int f = 0; f < 2; ++f)
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(evaluateFunction(read.functions[f], xs[i]), cpfg[f][i], cpfgTolerance(cpfg[f][i]))
                << f << " " << xs[i];
}

// cpfg would search for ever for an x the curve never reaches; here the search stops.
TEST(FunctionFile, ACurveShortOfXStillEvaluates) {
    const FunctionReadResult read = readOk("short.func", "range: 0 1\npoints: 4\n0 0\n0.1 1\n0.2 2\n0.3 3\n", -1);
    EXPECT_NEAR(evaluateFunction(read.function, 0.9), 3.0, 1e-6); // the curve's end
}

struct MalformedFunctionFile {
    const char* text;
    int line, column;
    const char* message; // a part of the diagnostic's message
};

TEST(FunctionFile, MalformedFilesAreReportedWhereTheyGoWrong) {
    const MalformedFunctionFile cases[] = {
        {"points: 4\n", 1, 1, "not a function file"},
        {"fver 2 0\nname: a\n", 1, 5, "unsupported function file version"},
        {"range: 0 1\npoints: 3\n0 0\n0.5 1\n1 0\n", 2, 9, "malformed number of points"},
        {"range: 0 1\npoints: 4\n0 0\n0.5 x\n", 4, 5, "malformed point"},
        {"range: 0 1\npoints: 4\n0 0\n0.5 1 2\n", 4, 7, "unexpected text"},
        {"range: 0 1\npoints: 4\n0 0\n0.5 1\n", 5, 1, "the file ends too early"},
        {"fver 1 1\nname: a\nsamples: 10\npoints: 4\n", 4, 1, "expected 'flip:'"},
        {"fver 1 1\nname: a\nsamples: 999999\n", 3, 10, "malformed 'samples:' value"},
        {"fver 1 1\nname: a\nsamples: 1\nflip: off\npoints: 4\n0 0 0\n0 0 0\n0 0 1\n1 1 1\n", 5, 9,
         "fewer than 4 points"},
        {"fver 1 1\nname: a\nsamples: 1\nflip: off\npoints: 4\n0 0 9999\n", 6, 5, "too many points"},
        {"range: 0 1\npoints: 4\n0 nan\n", 3, 3, "malformed point"},
    };
    for (const MalformedFunctionFile& bad : cases) {
        TempFunction file("bad.func", bad.text);
        const FunctionReadResult read = readFunctionFile(file.path, 100);
        ASSERT_FALSE(read.ok()) << bad.text;
        const Diagnostic& first = read.diagnostics.front();
        EXPECT_EQ(first.file, file.path.string());
        EXPECT_EQ(first.line, bad.line) << bad.text << first.message;
        EXPECT_EQ(first.column, bad.column) << bad.text << first.message;
        EXPECT_NE(first.message.find(bad.message), std::string::npos) << bad.text << first.message;
        EXPECT_EQ(evaluateFunction(read.function, 0.5), 0.0); // nothing read: no curve
    }
}

TEST(FunctionFile, TooManySamplesFromTheViewFileAreRefused) {
    TempFunction file("b.func", kRangeFormat);
    const FunctionReadResult read = readFunctionFile(file.path, kMaxFunctionSamples + 1);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.diagnostics[0].message.find("asks for 65537 samples, too many"), std::string::npos);
}

// Each sample is a bisection: a set's functions share the bound, or a
// 4 KiB set of 65536-sample functions would take minutes.
TEST(FunctionFile, ASetsFunctionsShareTheBoundOnSamples) {
    const std::string function = "fver 1 1\nname: f\nsamples: 40000\nflip: off\npoints: 4\n0 0\n0 1\n1 1\n1 0\n";
    TempFunction set("big.fset", "funcgalleryver 1 1\nitems: 2\n" + function + function);
    const FunctionSetReadResult read = readFunctionSet(set.path);
    ASSERT_EQ(read.diagnostics.size(), 1u);
    EXPECT_EQ(read.diagnostics[0].line, 14); // the second function's "samples:"
    EXPECT_EQ(read.diagnostics[0].column, 10);
    EXPECT_NE(read.diagnostics[0].message.find("40000 samples, too many"), std::string::npos);
    ASSERT_EQ(read.functions.size(), 1u);
    EXPECT_EQ(read.functions[0].samples.size(), 40000u);
}

TEST(FunctionFile, AMissingFileIsNamed) {
    const std::filesystem::path missing = std::filesystem::temp_directory_path() / "plantfield_no_such.func";
    const FunctionReadResult read = readFunctionFile(missing);
    ASSERT_EQ(read.diagnostics.size(), 1u);
    EXPECT_EQ(read.diagnostics[0].file, missing.string());
    EXPECT_NE(read.diagnostics[0].message.find(missing.string()), std::string::npos);
    EXPECT_NE(read.diagnostics[0].message.find("missing"), std::string::npos);
    const FunctionSetReadResult set = readFunctionSet(missing);
    EXPECT_FALSE(set.ok());
}

TEST(FunctionFile, MalformedFunctionSetsAreReported) {
    TempFunction notSet("s.fset", kRangeFormat);
    EXPECT_EQ(readFunctionSet(notSet.path).diagnostics.at(0).message, "not a function set");
    TempFunction shortSet("t.fset", std::string("funcgalleryver 1 1\nitems: 2\n") + kRangeFormat);
    const FunctionSetReadResult read = readFunctionSet(shortSet.path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.diagnostics[0].line, 9); // the end, where the second function should begin
}

} // namespace
} // namespace lsys::vlab
