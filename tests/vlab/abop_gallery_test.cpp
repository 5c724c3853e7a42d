// The ABOP gallery (data/plants/abop): systems of The Algorithmic Beauty of
// Plants (Prusinkiewicz & Lindenmayer 1990; the figure in each name) written
// as cpfg writes them, each a vlab object: plant.l, plant.v, plant.map and a
// specifications whose cpfg command line names them. Every object is derived
// here and compared, module for module with parameters within 1e-4 relative
// (firstDifference, as `lsys derive --compare`), with the string vlab's cpfg
// derives from it (cpfg 6.6 built from vlab's sources, `cpfg -str`): the
// object's cpfg.str where that is under 64 KB, otherwise the summary pinned
// below. The scene data/scenes/abop_gallery.json shows them all.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <ostream>
#include <set>
#include <string>

#include "lsystem/dialects/dialect.h"
#include "lsystem/language/module_string.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/vlab/object.h"

namespace lsys {
namespace {

namespace fs = std::filesystem;

const fs::path kGallery = fs::path(PLANTFIELD_DATA_DIR) / "plants" / "abop";

// A cpfg string too long to keep (64 KB or more), from cpfg (vlab 'cpfg -str'):
// FNV-1a 64 of the module names, each followed by a 0x1f byte (the whole
// string when no module has parameters); the sum of all parameters; the first
// and the last 16 modules as cpfg writes them.
struct LargeString {
    uint64_t nameHash;
    double parameterSum;
    const char* first;
    const char* last;
};

struct GalleryObject {
    const char* name;
    int derivationLength;
    double angle;                          // the view file's angle increment: the figure's delta
    size_t modules;                        // from cpfg (vlab 'cpfg -str')
    const char* exact = nullptr;           // the whole string, from cpfg, for the short ones
    std::optional<LargeString> large = {}; // cpfg.str would be 64 KB or more
};

// Derivation lengths, angles (the figures') and, from cpfg (vlab 'cpfg -str'), the module counts, the
// whole string of the short ones and the summaries of those whose cpfg.str is not kept.
const GalleryObject kObjects[] = {
    {"fig1_6_quadratic_koch_island", 3, 90, 3804, nullptr},
    {"fig1_7a_quadratic_koch_island", 2, 90, 2212, nullptr},
    {"fig1_7b_quadratic_snowflake", 4, 90, 1250, nullptr},
    {"fig1_8_islands_and_lakes", 2, 90, 2596, nullptr},
    {"fig1_9a_koch_curve", 4, 90, 30428, nullptr},
    {"fig1_9b_koch_curve", 4, 90, 16007, nullptr},
    {"fig1_9c_koch_curve", 3, 90, 2288, nullptr},
    {"fig1_9d_koch_curve", 4, 90, 4999, nullptr},
    {"fig1_9e_koch_curve", 5, 90, 25000, nullptr},
    {"fig1_9f_koch_curve", 4, 90, 5000, nullptr},
    {"fig1_10a_dragon_curve", 10, 90, 3071, nullptr},
    {"fig1_10b_sierpinski_gasket", 6, 60, 1457, nullptr},
    {"fig1_11a_hexagonal_gosper_curve", 4, 60, 5602, nullptr},
    {"fig1_11b_quadratic_gosper_curve", 2, 90, 1094, nullptr},
    {"fig1_19_hilbert_curve_3d", 2, 90, 271,
     "A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//-F+|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//F|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//"
     "+F-|CFB-F+B|FA&F^A&&FB-F+B|FC//&F^|CFB-F+B|FA&F^A&&FB-F+B|FC//-F+&&|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//"
     "F|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//+F+A&F^CFB^F^D^^-F-D^|F^B|FC^F^A////"},
    {"fig1_24a_bracketed_plant", 5, 25.7, 7811, nullptr},
    {"fig1_24b_bracketed_plant", 5, 20, 9373, nullptr},
    {"fig1_24c_bracketed_plant", 4, 22.5, 11116, nullptr},
    {"fig1_24d_bracketed_plant", 7, 20, 13956, nullptr},
    {"fig1_24e_bracketed_plant", 7, 25.7, 12863, nullptr},
    {"fig1_24f_bracketed_plant", 5, 22.5, 6263, nullptr},
    {"fig1_25_bush", 7, 22.5, 77399, nullptr,
     LargeString{0x02985d5fca5bbbca, 0.0, "[&FL/////S/////F", "//;[&FL!A]]]]]]]"}},
    {"fig1_26_flowering_plant", 5, 18, 15325, nullptr},
    {"fig1_31a_hogeweg", 30, 22.5, 6910, nullptr},
    {"fig1_31b_hogeweg", 30, 22.5, 19199, nullptr},
    {"fig1_31c_hogeweg", 26, 25.75, 2926, nullptr},
    {"fig1_31d_hogeweg", 24, 25.75, 5789, nullptr},
    {"fig1_31e_hogeweg", 26, 22.5, 2428, nullptr},
    {"fig1_37a_row_of_trees", 6, 86, 9557, nullptr},
    {"fig1_37b_row_of_trees", 10, 86, 7793, nullptr},
    {"fig2_6a_monopodial_tree", 10, 45, 7162, nullptr},
    {"fig2_6b_monopodial_tree", 10, 45, 7162, nullptr},
    {"fig2_6c_monopodial_tree", 10, 45, 7162, nullptr},
    {"fig2_6d_monopodial_tree", 10, 45, 7162, nullptr},
    {"fig2_7a_sympodial_tree", 10, 45, 11253, nullptr},
    {"fig2_7b_sympodial_tree", 10, 45, 11253, nullptr},
    {"fig2_7c_sympodial_tree", 10, 45, 11253, nullptr},
    {"fig2_7d_sympodial_tree", 10, 45, 11253, nullptr},
    {"fig2_8a_ternary_tree", 6, 30, 6556, nullptr},
    {"fig2_8b_ternary_tree", 8, 30, 59044, nullptr,
     LargeString{
         0xf20c83a547352cc8, 1791579.3616196553,
         "!(80.981)F(457.596)/"
         "(45)!(80.981)F(103.155)[&(18.95)F(103.155)!(46.7558)F(93.0163)[&(18.95)F(93.0163)!(26.9952)F(83.8741)[",
         "F(50)A]/(137.5)[&(18.95)F(50)A]]]]]]]]"}},
    {"fig2_8c_ternary_tree", 8, 30, 59044, nullptr,
     LargeString{0xf20c83a547352cc8, 2204098.487620105,
                 "!(80.981)F(21079.2)/"
                 "(45)!(80.981)F(2944.02)[&(22.5)F(2944.02)!(46.7558)F(1644.71)[&(22.5)F(1644.71)!(26.9952)F(918.83)[",
                 "F(50)A]/(157.5)[&(22.5)F(50)A]]]]]]]]"}},
    {"fig2_8d_ternary_tree", 6, 30, 6556, nullptr},
    {"fig5_5_cordate_leaf", 20, 10, 746, nullptr},
    {"fig5_6_rose_leaf", 25, 60, 1388, nullptr},
    {"fig5_11d_compound_leaf", 30, 45, 700721, nullptr,
     LargeString{0x66437daedd33c799, 604373.1174590943,
                 "F(404.807)[+F(143.788)[+F(51.0737)[+F(18.1414)[+F(6.44386)[+F(2.28887)",
                 "[-A(3)]F(1.23)F(1)[+A(4)][-A(4)]F(1)A(0)"}},
    {"fig5_11e_compound_leaf", 45, 45, 2101671, nullptr,
     LargeString{0xf9e08b9fbf44ff07, 2719003.45671369,
                 "F(1000.41)[+F(284.899)[+F(81.1342)[+F(23.1056)[+F(6.58007)[+F(1.87389)",
                 "[-A(6)]F(1.17)F(1)[+A(7)][-A(7)]F(1)A(0)"}},
    {"fig5_12a_alternating_leaf", 20, 45, 106261, nullptr,
     LargeString{0xb35c214203282e08, 89109.46558000488,
                 "F(344.54)[+F(186.278)[+F(100.713)[+F(54.451)[+F(29.4393)[+F(15.9166)",
                 "A(0)]F(1.8496)F(1.36)[+A(0)]F(1.36)F(1)[-B(1)]F(1)A(0)"}},
    {"fig5_12b_alternating_leaf", 34, 45, 132451, nullptr,
     LargeString{0x2042e859d4d4ba9e, 139807.30607997923,
                 "F(235.563)[+F(102.967)[+F(45.0076)[+F(19.6733)[+F(8.59936)[+F(3.75886)",
                 "B(2)]F(1.3924)F(1.18)[+A(3)]F(1.18)F(1)[-B(4)]F(1)A(0)"}},
    {"fig5_12c_alternating_leaf", 46, 45, 164563, nullptr,
     LargeString{0xa166a02a298c178f, 224074.81426000645,
                 "F(244.641)[+F(92.0243)[+F(34.6158)[+F(13.0211)[+F(4.89801)[+F(1.84244)",
                 "B(5)]F(1.2769)F(1.13)[+A(6)]F(1.13)F(1)[-B(7)]F(1)A(0)"}},
};

// gtest names the object rather than dumping its bytes.
void PrintTo(const GalleryObject& object, std::ostream* out) { *out << object.name; }

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint64_t nameHash(const ModuleString& string, const SymbolTable& symbols) {
    uint64_t hash = 0xcbf29ce484222325ull;
    const auto mix = [&](unsigned char byte) {
        hash ^= byte;
        hash *= 0x100000001b3ull;
    };
    for (size_t i = 0; i < string.size(); ++i) {
        for (const char c : symbols.name(string.symbols[i])) mix(static_cast<unsigned char>(c));
        mix(0x1f);
    }
    return hash;
}

ModuleString slice(const ModuleString& string, size_t begin, size_t end) {
    ModuleString part;
    for (size_t i = begin; i < end; ++i) part.push(string.symbols[i], string.parameters(i));
    return part;
}

class AbopGallery : public ::testing::TestWithParam<GalleryObject> {
protected:
    fs::path folder() const { return kGallery / GetParam().name; }
};

// The L-system reads as cpfg (a .l file) and derives, in its derivation
// length, the string cpfg derives.
TEST_P(AbopGallery, DerivesTheStringCpfgDerives) {
    const GalleryObject& object = GetParam();
    const fs::path file = folder() / "plant.l";
    ParseResult result = loadDialectFile(file.string());
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, readFile(file));
    EXPECT_TRUE(result.warnings.empty()) << formatDiagnostics(result.warnings, readFile(file));
    const Grammar& grammar = result.grammar;
    EXPECT_EQ(grammar.derivationLength, object.derivationLength);

    const ModuleString string = derive(grammar);
    EXPECT_EQ(string.size(), object.modules);
    if (object.exact) {
        EXPECT_EQ(toString(string, grammar.symbols), object.exact);
    }

    const fs::path stored = folder() / "cpfg.str";
    if (!object.large) {
        ASSERT_TRUE(fs::exists(stored)) << stored;
        EXPECT_LT(fs::file_size(stored), 64u << 10);
        const std::optional<std::string> difference = firstDifference(string, grammar.symbols, readFile(stored));
        EXPECT_FALSE(difference) << *difference;
        return;
    }
    EXPECT_FALSE(fs::exists(stored)) << "a cpfg.str is kept, yet the string is pinned by its summary";
    const LargeString& large = *object.large;
    EXPECT_EQ(nameHash(string, grammar.symbols), large.nameHash);
    double sum = 0;
    for (const float value : string.params) sum += value;
    EXPECT_NEAR(sum, large.parameterSum, 1e-4 * std::abs(large.parameterSum));
    ASSERT_GE(string.size(), 16u);
    const std::optional<std::string> first = firstDifference(slice(string, 0, 16), grammar.symbols, large.first);
    EXPECT_FALSE(first) << "the first modules: " << *first;
    const std::optional<std::string> last =
        firstDifference(slice(string, string.size() - 16, string.size()), grammar.symbols, large.last);
    EXPECT_FALSE(last) << "the last modules: " << *last;
}

// A vlab object: the specifications' cpfg command line names the L-system,
// the view file and the colour map, and loading the object reads the view
// file's angle.
TEST_P(AbopGallery, IsAVlabObject) {
    const GalleryObject& object = GetParam();
    const std::string specifications = readFile(folder() / "specifications");
    EXPECT_NE(specifications.find("\t\tcpfg -m plant.map plant.l plant.v\n"), std::string::npos) << specifications;
    std::string problem;
    const std::optional<vlab::ObjectFiles> files = vlab::findObjectFiles(folder(), problem);
    ASSERT_TRUE(files) << problem;
    EXPECT_EQ(files->lsystem.filename().string(), "plant.l");
    EXPECT_EQ(files->view.filename().string(), "plant.v");
    EXPECT_EQ(files->colorMap.filename().string(), "plant.map");
    EXPECT_EQ(fs::file_size(folder() / "plant.map"), 768u); // 256 RGB byte triples

    const std::string view = readFile(folder() / "plant.v");
    EXPECT_NE(view.find("initial line width: "), std::string::npos);
    EXPECT_NE(view.find("line width increment: "), std::string::npos);
    EXPECT_NE(view.find("initial color: "), std::string::npos);
    EXPECT_NE(view.find("color increment: "), std::string::npos);

    const vlab::PlantFile plant = vlab::loadObject(folder());
    ASSERT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    EXPECT_TRUE(plant.parsed.warnings.empty()) << formatDiagnostics(plant.parsed.warnings, plant.source);
    EXPECT_NEAR(plant.parsed.grammar.angle, object.angle, 1e-4);
    EXPECT_EQ(plant.parsed.grammar.derivationLength, object.derivationLength);
}

std::string objectName(const ::testing::TestParamInfo<GalleryObject>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Objects, AbopGallery, ::testing::ValuesIn(kObjects), objectName);

// Every folder of the gallery is pinned above, and every pinned object has its folder.
TEST(AbopGalleryFolder, EveryObjectIsPinned) {
    std::set<std::string> folders;
    for (const fs::directory_entry& entry : fs::directory_iterator(kGallery))
        if (entry.is_directory()) folders.insert(entry.path().filename().string());
    std::set<std::string> pinned;
    for (const GalleryObject& object : kObjects) pinned.insert(object.name);
    EXPECT_EQ(folders, pinned);
    EXPECT_GE(pinned.size(), 20u);
}

// The gallery scene shows every object (a species whose lsystem is the object's folder).
TEST(AbopGalleryFolder, TheSceneShowsEveryObject) {
    const std::string scene = readFile(fs::path(PLANTFIELD_DATA_DIR) / "scenes" / "abop_gallery.json");
    ASSERT_FALSE(scene.empty());
    for (const GalleryObject& object : kObjects)
        EXPECT_NE(scene.find("\"../plants/abop/" + std::string(object.name) + "\""), std::string::npos) << object.name;
}

} // namespace
} // namespace lsys
