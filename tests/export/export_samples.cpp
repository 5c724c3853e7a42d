// Writes the glTF files that the GltfValidator ctest hands to the Khronos
// glTF-Validator: samplePlant() and helixPlant() in every form and geometry
// as .gltf and .glb, an empty plant, and in broken/ a file the validator must reject (so the
// test is seen to be able to fail).
// Usage: export_samples DIR
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

#include "lsystem/plant_export.h"
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

// PREFIX_{flat,instanced}_{frusta,tubes}.{gltf,glb}
void exportEveryForm(const lsys::PlantAsset& plant, const fs::path& prefix) {
    for (const auto form : {lsys::ExportForm::Flat, lsys::ExportForm::Instanced}) {
        for (const auto segments : {lsys::SegmentGeometry::Frusta, lsys::SegmentGeometry::GeneralizedCylinders}) {
            lsys::ExportOptions options;
            options.form = form;
            options.segments = segments;
            const std::string name = prefix.string() + (form == lsys::ExportForm::Flat ? "_flat" : "_instanced") +
                                     (segments == lsys::SegmentGeometry::Frusta ? "_frusta" : "_tubes");
            for (const char* extension : {".gltf", ".glb"}) lsys::exportPlant(plant, name + extension, options);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: export_samples DIR\n");
        return 2;
    }
    try {
        const fs::path dir = argv[1];
        fs::remove_all(dir);
        fs::create_directories(dir / "broken");
        exportEveryForm(plantfield::test::samplePlant(), dir / "sample");
        exportEveryForm(plantfield::test::helixPlant(60), dir / "helix");
        lsys::exportPlant(lsys::PlantAsset{}, dir / "empty.glb");
        writeBroken(dir / "sample_flat_frusta.gltf", dir / "broken" / "accessor_out_of_bounds.gltf");
    } catch (const std::exception& error) {
        std::fprintf(stderr, "export_samples: %s\n", error.what());
        return 1;
    }
    return 0;
}
