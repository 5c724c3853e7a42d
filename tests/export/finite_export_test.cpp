// Exports never carry NaN or infinity: a plant whose geometry holds one (a
// size past the float range upstream) is refused with a message naming the
// file, and nothing is written, in every format and in the instanced form.
#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"

#include <gtest/gtest.h>

#include <limits>

#include "gltf_reading.h"
#include "sample_plants.h"

namespace {

namespace fs = std::filesystem;

class FiniteExport : public plantfield::test::ExportDirTest {
protected:
    // The message of exporting `asset` to `name`, which must fail and leave no file.
    std::string failureOf(const lsys::PlantAsset& asset, const std::string& name) const {
        try {
            lsys::exportPlant(asset, dir / name);
            ADD_FAILURE() << name << " was written";
        } catch (const std::runtime_error& error) {
            EXPECT_TRUE(fs::is_empty(dir)) << name;
            return error.what();
        }
        return {};
    }
};

TEST_F(FiniteExport, APositionPastTheFloatRangeIsRefusedInEveryFormat) {
    lsys::PlantAsset asset = plantfield::test::samplePlant();
    asset.primitives[0].frame.position.x = std::numeric_limits<float>::infinity();
    for (const std::string name : {"plant.glb", "plant.gltf", "plant.obj"})
        EXPECT_EQ(failureOf(asset, name), "export " + (dir / name).string() +
                                              ": the plant's geometry holds a position that is not a finite number "
                                              "(NaN or infinity): its sizes or scales are past the float range");
}

TEST_F(FiniteExport, AnInstancePlacedPastTheFloatRangeIsRefused) {
    lsys::InstanceGraph graph = plantfield::test::sampleGraph();
    ASSERT_FALSE(graph.instances.empty());
    graph.instances[0].frame.position.y = std::numeric_limits<float>::infinity();
    try {
        lsys::exportInstanceGraph(graph, lsys::SurfaceLibrary{}, dir / "graph.glb");
        ADD_FAILURE() << "graph.glb was written";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("is placed at a position or rotation that is not a finite number"),
                  std::string::npos)
            << error.what();
        EXPECT_TRUE(fs::is_empty(dir));
    }
}

} // namespace
