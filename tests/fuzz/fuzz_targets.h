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
// build it under a 256 MiB memory budget.
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

} // namespace pf::fuzz
