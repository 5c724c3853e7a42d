#include "fuzz_targets.h"
#include "input_file.h"

#include "lsystem/turtle/surfaces.h"

#include <cstring>

namespace pf::fuzz {

void runGltfInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    try {
        (void)lsys::loadSurfaceFile(
            writeInputFile(data, size, binary ? "meshes-input/input.glb" : "meshes-input/input.gltf"), "fuzz");
    } catch (const lsys::SurfaceError&) {
        // A clear error naming the file is the right outcome.
    }
}

} // namespace pf::fuzz
