// Malformed component files and graphs past their budgets: each must fail
// with a ComponentError naming file:line:column, the JSON pointer and what
// was wrong (with a did-you-mean for misspelt names). None may crash.
#include "component_test_support.h"
#include "lsystem/components/component_graph.h"

#include <gtest/gtest.h>

namespace lsys::components {
namespace {

struct BadFile {
    const char* name;
    const char* text;
    const char* lineColumn; // where the error must point
    const char* message;    // what it must say
};

void PrintTo(const BadFile& bad, std::ostream* out) { *out << bad.name; }

class BadComponentFile : public testing::TestWithParam<BadFile> {};

TEST_P(BadComponentFile, FailsWithFileLineColumnAndMessage) {
    const BadFile& bad = GetParam();
    const std::filesystem::path file = test::writeComponentFile(std::string(bad.name) + ".comp.json", bad.text);
    try {
        loadComponentPlant(file);
        FAIL() << "loaded without an error";
    } catch (const ComponentError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(file.string() + ":" + bad.lineColumn + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(bad.message), std::string::npos) << what;
    }
}

// A stem component "s" and the text after it, in a graph rooted at "s".
#define ONE_STEM(rest) "{\n\"root\": \"s\",\n\"components\": {\n\"s\": {\"kind\": \"stem\"" rest "}\n}\n}"

INSTANTIATE_TEST_SUITE_P(
    Components, BadComponentFile,
    testing::Values(
        BadFile{"not_json", "{\n  \"root\": ,\n}", "2:11", "unexpected ','"},
        BadFile{"unknown_top_key", "{\n  \"rooot\": \"s\"\n}", "2:3",
                "/rooot is an unknown key; did you mean \"root\"?"},
        BadFile{"unknown_kind", "{\n\"root\": \"s\",\n\"components\": {\n\"s\": {\"kind\": \"stme\"}\n}\n}", "4:15",
                "/components/s/kind is an unknown component kind \"stme\"; did you mean \"stem\"?"},
        BadFile{"missing_kind", "{\n\"root\": \"s\",\n\"components\": {\n\"s\": {}\n}\n}", "4:6",
                "/components/s needs \"kind\""},
        BadFile{"unknown_attribute", ONE_STEM(", \"lenght\": 2"), "4:23",
                "/components/s/lenght is an unknown key; did you mean \"length\"?"},
        BadFile{"attribute_of_another_kind", ONE_STEM(", \"branch_angle\": 2"), "4:23",
                "/components/s/branch_angle is an unknown key (expected one of \"kind\""},
        BadFile{"out_of_range", ONE_STEM(", \"detail\": 0"), "4:33",
                "/components/s/detail must be an integer in [1, 256] (got 0)"},
        BadFile{"negative_radius_in_spline", ONE_STEM(", \"radius\": [0.1, -0.2]"), "4:39",
                "/components/s/radius/1 must be a number in [0, 1000000]"},
        BadFile{"length_near_the_float_maximum", ONE_STEM(", \"length\": 3e38"), "4:33",
                "/components/s/length must be a number in (0, 1000000] (got 3e38)"},
        BadFile{"shape_point_near_the_float_maximum", ONE_STEM(", \"shape\": [[0, 0, 0], [0, 3.4e38, 0]]"), "4:44",
                "/components/s/shape/1 must be an array of 3 numbers in [-1000000, 1000000]"},
        BadFile{"too_few_shape_points", ONE_STEM(", \"shape\": [[0, 0, 0]]"), "4:32",
                "/components/s/shape needs at least 2 control points"},
        BadFile{"mixed_tangents", ONE_STEM(", \"shape\": [[0, 0, 0], {\"at\": [0, 1, 0], \"tangent\": [0, 1, 0]}]"),
                "4:44", "/components/s/shape/1 mixes points with and without tangents"},
        BadFile{"unknown_child", ONE_STEM(", \"children\": [\"s\", \"leef\"]}, \"leaf\": {\"kind\": \"leaf\""), "4:41",
                "/components/s/children/1 names no component \"leef\"; did you mean \"leaf\"?"},
        BadFile{"unknown_root", "{\n\"root\": \"trunc\",\n\"components\": {\n\"trunk\": {\"kind\": \"stem\"}\n}\n}",
                "2:9", "/root names no component \"trunc\"; did you mean \"trunk\"?"},
        BadFile{"unknown_material", ONE_STEM(", \"material\": \"brak\""), "4:35",
                "/components/s/material names no material \"brak\"; did you mean \"bark\"?"},
        BadFile{"cycle",
                "{\n\"root\": \"a\",\n\"components\": {\n\"a\": {\"kind\": \"stem\", \"children\": [\"b\"]},\n"
                "\"b\": {\"kind\": \"radial\", \"children\": [\"a\"]}\n}\n}",
                "5:38", "/components/b/children/0 makes a cycle (a → b → a)"},
        BadFile{"cycle_through_a_tree_stem",
                "{\n\"root\": \"t\",\n\"components\": {\n\"s\": {\"kind\": \"stem\", \"children\": [\"t\"]},\n"
                "\"t\": {\"kind\": \"tree\", \"stem\": \"s\"}\n}\n}",
                "5:31", "/components/t/stem makes a cycle (s → t → s)"},
        BadFile{"tree_stem_not_a_stem",
                "{\n\"root\": \"t\",\n\"components\": {\n\"l\": {\"kind\": \"leaf\"},\n"
                "\"t\": {\"kind\": \"tree\", \"stem\": \"l\"}\n}\n}",
                "5:31", "/components/t/stem must name a stem component"},
        BadFile{"not_a_boolean",
                "{\n\"root\": \"t\",\n\"components\": {\n\"s\": {\"kind\": \"stem\"},\n"
                "\"t\": {\"kind\": \"tree\", \"stem\": \"s\", \"stem_visible\": 1}\n}\n}",
                "5:52", "/components/t/stem_visible must be true or false (got 1)"},
        BadFile{"tree_without_stem", "{\n\"root\": \"t\",\n\"components\": {\n\"t\": {\"kind\": \"tree\"}\n}\n}", "4:6",
                "/components/t needs \"stem\""},
        BadFile{"tree_end_before_start",
                "{\n\"root\": \"t\",\n\"components\": {\n\"s\": {\"kind\": \"stem\"},\n"
                "\"t\": {\"kind\": \"tree\", \"stem\": \"s\", \"start\": 0.8, \"end\": 0.2}\n}\n}",
                "5:57", "/components/t/end must not be less than \"start\""},
        BadFile{"outline_and_polygon",
                "{\n\"root\": \"l\",\n\"components\": {\n\"l\": {\"kind\": \"leaf\", \"outline\": [[0, 0], [0, 1]], "
                "\"polygon\": [[0, 0], [1, 0], [0, 1]]}\n}\n}",
                "4:52", "/components/l/polygon cannot be given together with \"outline\""},
        BadFile{"budget_out_of_range", "{\n\"root\": \"s\",\n\"budget\": {\"max_primitives\": 0}\n}", "3:30",
                "/budget/max_primitives must be an integer in [1, 100000000] (got 0)"},
        BadFile{"repeated_key", ONE_STEM(", \"length\": 1, \"length\": 2"), "4:36",
                "\"length\" is given twice in one object"},
        BadFile{"budget_of_instances",
                "{\n\"root\": \"t\",\n\"budget\": {\"max_instances\": 50},\n\"components\": {\n"
                "\"s\": {\"kind\": \"stem\", \"detail\": 1},\n"
                "\"t\": {\"kind\": \"tree\", \"stem\": \"s\", \"count\": 100, \"children\": [\"l\"]},\n"
                "\"l\": {\"kind\": \"leaf\"}\n}\n}",
                "7:6", "/components/l is drawn 100 times: the plant would draw 102 components, past the budget of 50"},
        BadFile{"budget_of_primitives",
                "{\n\"root\": \"s\",\n\"budget\": {\"max_primitives\": 100},\n\"components\": {\n"
                "\"s\": {\"kind\": \"stem\", \"detail\": 101}\n}\n}",
                "5:6", "/components/s is drawn once: the plant would draw 101 primitives, past the budget of 100"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ComponentFile, AGraphOfATrillionLeavesIsRefusedBeforeDrawing) {
    // Three nested trees of 10 000 nodes: 10¹² leaves, counted, not drawn.
    const std::filesystem::path file = test::writeComponentFile("trillion.comp.json", R"({
  "root": "a",
  "components": {
    "s": { "kind": "stem", "detail": 1 },
    "a": { "kind": "tree", "stem": "s", "count": 10000, "children": ["b"] },
    "b": { "kind": "tree", "stem": "s", "count": 10000, "children": ["c"] },
    "c": { "kind": "tree", "stem": "s", "count": 10000, "children": ["l"] },
    "l": { "kind": "leaf" }
  }
})");
    try {
        loadComponentPlant(file);
        FAIL() << "built a trillion leaves";
    } catch (const ComponentError& e) {
        EXPECT_NE(std::string(e.what()).find("/components/l is drawn 1000000000000 times"), std::string::npos)
            << e.what();
    }
}

// Every value within 10⁶, but scales of 10⁶ multiplied down eight trees
// pass the float range: refused at the first component drawn past it
// instead of a plant of infinities and NaNs. That is t5, at scale 10³⁰: the
// length of t4's stem segment (10²⁴ long) squares past float's limit, so
// the place along it where t5 is drawn is no number.
TEST(ComponentFile, ScalesMultipliedPastTheFloatRangeAreRefusedWhereTheyPassIt) {
    std::string components = "\"s\": {\"kind\": \"stem\", \"detail\": 1},\n\"l\": {\"kind\": \"leaf\"}";
    for (int i = 0; i < 8; ++i)
        components += ",\n\"t" + std::to_string(i) +
                      "\": {\"kind\": \"tree\", \"stem\": \"s\", \"count\": 1, \"scale\": 1e6, \"children\": [\"" +
                      (i < 7 ? "t" + std::to_string(i + 1) : std::string("l")) + "\"]}";
    const std::filesystem::path file = test::writeComponentFile(
        "huge_scales.comp.json", "{\n\"root\": \"t0\",\n\"components\": {\n" + components + "\n}\n}\n");
    try {
        loadComponentPlant(file);
        FAIL() << "drew a plant at scales up to 1e42";
    } catch (const ComponentError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":11:7: /components/t5 is drawn at a size or place past the "
                                                         "float range: the scales of the components drawing it "
                                                         "multiply past it");
    }
}

TEST(ComponentFile, MissingFileOrFolderIsAComponentError) {
    EXPECT_THROW(readComponentGraph(std::filesystem::current_path() / "absent.comp.json"), ComponentError);
    EXPECT_THROW(readComponentGraph(std::filesystem::current_path()), ComponentError);
}

TEST(ComponentFile, NamesEndingInCompJsonAreComponentFiles) {
    EXPECT_TRUE(isComponentFile("data/components/sunflower.comp.json"));
    EXPECT_FALSE(isComponentFile("data/scenes/valley.json"));
    EXPECT_FALSE(isComponentFile("data/plants/bush.lsys"));
}

} // namespace
} // namespace lsys::components
