// Component files sized to find quadratic steps in the reader: long chains
// of components and very long names. Each is read in time linear in the
// file (these took minutes when every component's location, or every
// did-you-mean, cost as much as the whole file); a chain deeper than any
// plant is refused at its place, before the recursive drawing.
#include "component_test_support.h"
#include "lsystem/components/component_graph.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace lsys::components {
namespace {

// "c00042": zero-padded, so the reader's (sorted) order is the chain's.
std::string chainName(int i) {
    char name[16];
    std::snprintf(name, sizeof name, "c%05d", i);
    return name;
}

// `length` stems of one segment, each drawing the next, one a line from line 4.
std::string chainFile(int length) {
    std::string text = "{\n\"root\": \"c00000\",\n\"components\": {\n";
    for (int i = 0; i < length; ++i) {
        text += "\"" + chainName(i) + "\": {\"kind\": \"stem\", \"detail\": 1";
        if (i + 1 < length) text += ", \"children\": [\"" + chainName(i + 1) + "\"]";
        text += i + 1 < length ? "},\n" : "}\n";
    }
    return text + "},\n\"budget\": {\"max_instances\": 100000}\n}\n";
}

TEST(ComponentSizes, AChainOfTwentyThousandComponentsIsRefusedAtItsPlace) {
    const std::filesystem::path file = test::writeComponentFile("chain.comp.json", chainFile(20000));
    try {
        readComponentGraph(file);
        FAIL() << "read a chain of 20000 components";
    } catch (const ComponentError& e) {
        // c18999 is the first to start a chain of 1001; it is on line 4 + 18999, its value at column 11.
        EXPECT_EQ(std::string(e.what()), file.string() +
                                             ":19003:11: /components/c18999 starts a chain of more than 1000 "
                                             "components, each drawing the next: deeper than any plant nests");
    }
}

TEST(ComponentSizes, AChainOfAThousandComponentsIsDrawnWithLocatedBudgetErrors) {
    const std::filesystem::path file = test::writeComponentFile("chain.comp.json", chainFile(1000));
    const ComponentGraph graph = readComponentGraph(file);
    ASSERT_EQ(graph.components.size(), 1000u);
    EXPECT_EQ(graph.components[999].location, file.string() + ":1003:11: /components/c00999");
    EXPECT_EQ(buildComponentPlant(graph).primitives.size(), 1000u);
}

// Names of 40 000 characters: an unknown one gets no did-you-mean (comparing
// it with each name would take the product of their lengths) and is still
// named at its place.
TEST(ComponentSizes, NamesTensOfThousandsOfCharactersLongAreReadAndRefusedQuickly) {
    const std::string a(40000, 'a'), b = std::string(39999, 'a') + "b", misspelt = std::string(39999, 'a') + "c";
    const std::string text = "{\n\"root\": \"" + a + "\",\n\"components\": {\n\"" + a +
                             "\": {\"kind\": \"stem\", \"children\": [\"" + b + "\"]},\n\"" + b +
                             "\": {\"kind\": \"radial\", \"children\": [\"" + misspelt + "\"]}\n}\n}\n";
    const std::filesystem::path file = test::writeComponentFile("long_names.comp.json", text);
    try {
        readComponentGraph(file);
        FAIL() << "read a reference to a missing component";
    } catch (const ComponentError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(file.string() + ":5:40037: /components/" + b + "/children/0 names no component \"" +
                                 misspelt + "\"",
                             0),
                  0u)
            << what.substr(0, 200);
        EXPECT_EQ(what.find("did you mean"), std::string::npos);
    }
}

} // namespace
} // namespace lsys::components
