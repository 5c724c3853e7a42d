// Writes the glTF files that the GltfValidator ctest hands to the Khronos
// glTF-Validator: samplePlant() and helixPlant() flat and sampleGraph()
// instanced, in both segment geometries as .gltf and .glb, an empty plant, and in broken/ a file the validator must
// reject (so the test is seen to be able to fail). Usage: export_samples DIR
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"
#include "sample_plants.h"

namespace fs = std::filesystem;

namespace {

// A valid export whose first accessor claims more elements than its buffer
// view holds: the validator's ACCESSOR_TOTAL_OFFSET_OUT_OF_BOUNDS.
void writeBroken(const fs::path& valid, const fs::path& broken) {
    tinygltf::TinyGLTF gltf;
    tinygltf::Model model;
    std::string error, warning;
    if (!gltf.LoadASCIIFromFile(&model, &error, &warning, valid.string())) throw std::runtime_error(error);
    model.accessors.at(0).count *= 2;
    if (!gltf.WriteGltfSceneToFile(&model, broken.string(), false, true, true, false))
        throw std::runtime_error("cannot write " + broken.string());
}

// PREFIX_{frusta,tubes}.{gltf,glb}, written by `write(path, segments)`.
template <typename Write>
void exportBothGeometries(const fs::path& prefix, Write write) {
    for (const auto segments : {lsys::SegmentGeometry::Frusta, lsys::SegmentGeometry::GeneralizedCylinders}) {
        const std::string name = prefix.string() + (segments == lsys::SegmentGeometry::Frusta ? "_frusta" : "_tubes");
        for (const char* extension : {".gltf", ".glb"}) write(name + extension, segments);
    }
}

// PREFIX_{frusta,tubes,drawn}.{gltf,glb}: the turtle's geometries and the drawn form.
void exportFlat(const lsys::PlantAsset& plant, const fs::path& prefix) {
    exportBothGeometries(prefix, [&](const fs::path& path, lsys::SegmentGeometry segments) {
        lsys::ExportOptions options;
        options.geometry = lsys::ExportGeometry::Turtle;
        options.segments = segments;
        lsys::exportPlant(plant, path, options);
    });
    for (const char* extension : {".gltf", ".glb"}) lsys::exportPlant(plant, prefix.string() + "_drawn" + extension);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: export_samples DIR\n");
        return 2;
    }
    try {
        const fs::path dir = argv[1];
        fs::remove_all(dir);
        fs::create_directories(dir / "broken");
        exportFlat(plantfield::test::samplePlant(), dir / "sample_flat");
        exportFlat(plantfield::test::helixPlant(60), dir / "helix_flat");
        const lsys::InstanceGraph graph = plantfield::test::sampleGraph();
        exportBothGeometries(dir / "graph_instanced", [&](const fs::path& path, lsys::SegmentGeometry segments) {
            lsys::GraphExportOptions options;
            options.geometry = lsys::ExportGeometry::Turtle;
            options.segments = segments;
            lsys::exportInstanceGraph(graph, lsys::SurfaceLibrary{}, path, options);
        });
        for (const char* extension : {".gltf", ".glb"})
            lsys::exportInstanceGraph(graph, lsys::SurfaceLibrary{},
                                      (dir / "graph_instanced_drawn").string() + extension);
        lsys::exportPlant(lsys::PlantAsset{}, dir / "empty.glb");
        writeBroken(dir / "sample_flat_frusta.gltf", dir / "broken" / "accessor_out_of_bounds.gltf");
    } catch (const std::exception& error) {
        std::fprintf(stderr, "export_samples: %s\n", error.what());
        return 1;
    }
    return 0;
}
