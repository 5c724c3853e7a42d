// lsys never writes over a file it reads (tools/lsys/output_check.h): render,
// export (and its .mtl) and ramify refuse an output that is the plant file, a
// vlab object's view, colour map or include file, through a symbolic or a
// hard link too, with exit 2 and the input left as it was.
#include "input_refusal.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pf::test::lsys_outputs {
namespace {

namespace fs = std::filesystem;

const std::string kLsys = LSYS_BIN;
const fs::path kData = PLANTFIELD_DATA_DIR;

fs::path copied(const fs::path& from, const fs::path& to) {
    fs::copy(from, to, fs::copy_options::recursive);
    return to;
}

// The ABOP monopodial tree as a vlab object (plant.l, plant.v, plant.map),
// its ratios moved to an #include'd file, in `dir`/tree.
fs::path vlabTree(const fs::path& dir) {
    const fs::path tree = copied(kData / "plants" / "abop" / "fig2_6a_monopodial_tree", dir / "tree");
    std::ifstream in(tree / "plant.l");
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    const std::string ratio = "#define r1 0.9";
    source.replace(source.find(ratio), ratio.size(), "#include \"ratios.h\"");
    std::ofstream(tree / "plant.l") << source;
    std::ofstream(tree / "ratios.h") << ratio << '\n';
    return tree;
}

TEST(LsysOutputs, RenderOntoItsPlantFileIsRefused) {
    const fs::path dir = emptyTestFolder("lsys_outputs");
    const fs::path plant = copied(kData / "plants" / "fractal_bush.lsys", dir / "bush.lsys");
    expectRefusedAsInput(kLsys + " render " + plant.string() + " -n 2 -o " + plant.string(), plant);
}

TEST(LsysOutputs, ExportWhoseMtlLandsOnThePlantFileIsRefused) {
    const fs::path dir = emptyTestFolder("lsys_outputs");
    const fs::path plant = copied(kData / "plants" / "fractal_bush.lsys", dir / "bush.mtl");
    expectRefusedAsInput(kLsys + " export " + plant.string() + " -n 2 -o " + (dir / "bush.obj").string(), plant);
    EXPECT_FALSE(fs::exists(dir / "bush.obj"));
}

TEST(LsysOutputs, OutputsOntoAVlabObjectsFilesAreRefused) {
    const fs::path dir = emptyTestFolder("lsys_outputs");
    const fs::path tree = vlabTree(dir);
    // Known only once the object is loaded: the folder named is no file.
    for (const char* file : {"plant.v", "plant.map", "ratios.h", "plant.l"}) {
        const fs::path link = dir / (std::string("to_") + file + ".glb");
        fs::create_symlink(tree / file, link);
        expectRefusedAsInput(kLsys + " export " + tree.string() + " -n 3 -o " + link.string(), tree / file);
    }
    fs::create_hard_link(tree / "plant.v", dir / "view.png");
    expectRefusedAsInput(kLsys + " render " + tree.string() + " -n 3 -o " + (dir / "view.png").string(),
                         tree / "plant.v");
}

TEST(LsysOutputs, RamifyOntoItsRamificationFileIsRefused) {
    const fs::path dir = emptyTestFolder("lsys_outputs");
    const fs::path oak = copied(kData / "ramified" / "oak.ram.json", dir / "oak.ram.json");
    expectRefusedAsInput(kLsys + " ramify " + oak.string() + " -o " + oak.string(), oak);
    fs::create_symlink(oak, dir / "tree.lsys");
    expectRefusedAsInput(kLsys + " ramify " + oak.string() + " -o " + (dir / "tree.lsys").string(), oak);
}

} // namespace
} // namespace pf::test::lsys_outputs
