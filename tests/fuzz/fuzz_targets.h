// The fuzz targets: one input each, shared by the libFuzzer binaries
// (clang with -DPLANTFIELD_FUZZ=ON, tools/fuzz.sh) and the corpus replay
// test, so both exercise the same path. Each returns normally for any input:
// a malformed one ends in the loader's own error, which the target catches;
// any other exception, a crash or a sanitizer report is a bug.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pf::fuzz {

// Parse as a plant file in any dialect; when it parses, derive a few steps
// under a small module budget and run the turtle.
void runLsysInput(const uint8_t* data, size_t size);
// Load as a scene file (engine/scene: JSON, validation, paths, seeds) and
// derive its placement rules.
void runSceneInput(const uint8_t* data, size_t size);
// Load as a component plant (lsystem/components, docs/COMPONENTS.md) and
// build it under a 64 MiB memory budget.
void runComponentsInput(const uint8_t* data, size_t size);
// Load as a glTF surface mesh (.glb when it starts with the binary magic).
void runGltfInput(const uint8_t* data, size_t size);
// The readers of a vlab object's files (lsystem/vlab, docs/VLAB.md): a view
// file's text; a function file in either format and as a function set,
// evaluated; a surface file, tessellated; a colour map and a material file.
void runViewInput(const uint8_t* data, size_t size);
void runFuncInput(const uint8_t* data, size_t size);
void runSurfaceInput(const uint8_t* data, size_t size);
void runColorInput(const uint8_t* data, size_t size);
// Parse as a ramification matrix file (lsystem/ramification,
// docs/RAMIFICATION.md); when it parses, generate the tree within 500
// branches and draw it under a 64 MiB memory budget.
void runRamificationInput(const uint8_t* data, size_t size);
// Parse as a terrain L-system (docs/TERRAIN_LSYSTEMS.md), derive its
// mountains under a 256 MiB budget and raise them on a small height field.
void runTerrainInput(const uint8_t* data, size_t size);
// Load as a cloud L-system (engine/scene/cloud_spheres.h): derive, interpret,
// keep its spheres and fit them to a cloud's box.
void runCloudInput(const uint8_t* data, size_t size);

} // namespace pf::fuzz
