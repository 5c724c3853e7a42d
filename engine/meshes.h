// Procedural meshes in the layouts the shaders pull from storage buffers.
#pragma once

#include "shaders/layouts.h"

#include <cstdint>
#include <vector>

namespace pf {

struct MeshData {
    std::vector<gpu::MeshVertex> vertices;
    std::vector<uint32_t> indices;
};

// A closed unit cylinder along +y from 0 to 1 with radius 1: `sides` quads
// around and a cap at each end; counter-clockwise seen from outside.
MeshData makeCylinderMesh(uint32_t sides);

} // namespace pf
