#include "engine/meshes.h"

#include <cmath>
#include <numbers>

namespace pf {

MeshData makeCylinderMesh(uint32_t sides) {
    MeshData mesh;
    auto ring = [&](float y, float side, float normalY) {
        const uint32_t first = uint32_t(mesh.vertices.size());
        for (uint32_t i = 0; i < sides; ++i) {
            const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(sides);
            const float c = std::cos(a), s = std::sin(a);
            mesh.vertices.push_back({{c, y, s, 0.0f}, {side * c, normalY, side * s, side}});
        }
        return first;
    };

    const uint32_t bottom = ring(0.0f, 1.0f, 0.0f);
    const uint32_t top = ring(1.0f, 1.0f, 0.0f);
    for (uint32_t i = 0; i < sides; ++i) {
        const uint32_t j = (i + 1) % sides;
        mesh.indices.insert(mesh.indices.end(), {bottom + i, top + i, bottom + j, bottom + j, top + i, top + j});
    }

    // Caps have their own vertices so their normals run along the axis.
    for (float y : {0.0f, 1.0f}) {
        const float normalY = y > 0.5f ? 1.0f : -1.0f;
        const uint32_t center = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back({{0.0f, y, 0.0f, 0.0f}, {0.0f, normalY, 0.0f, 0.0f}});
        const uint32_t rim = ring(y, 0.0f, normalY);
        for (uint32_t i = 0; i < sides; ++i) {
            const uint32_t j = (i + 1) % sides;
            if (normalY > 0)
                mesh.indices.insert(mesh.indices.end(), {center, rim + j, rim + i});
            else
                mesh.indices.insert(mesh.indices.end(), {center, rim + i, rim + j});
        }
    }
    return mesh;
}

} // namespace pf
