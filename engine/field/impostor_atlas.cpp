// The impostor box and the billboard meshes; the frames' views are
// shaders/shared/impostor_frame.h, the bake impostor_bake.cpp.
#include "engine/field/impostor_atlas.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pf {

glm::vec4 impostorQuadOf(const gpu::PlantModel& model) {
    float x = std::max(std::abs(model.boxMin.x), std::abs(model.boxMax.x));
    float z = std::max(std::abs(model.boxMin.z), std::abs(model.boxMax.z));
    // An empty model still gets a frame of non-zero size.
    float radius = std::max(std::sqrt(x * x + z * z), 1e-3f);
    float top = std::max(model.boxMax.y, model.boxMin.y + 1e-3f);
    return {radius, model.boxMin.y, top, radius};
}

MeshRange appendBillboardMesh(PlantModelPool& pool, uint32_t quads) {
    if (quads < 1 || quads > 3) throw std::runtime_error("billboard mesh: quads must be 1, 2 or 3");
    MeshRange range;
    range.firstIndex = uint32_t(pool.indices.size());
    range.indexCount = 3 * (kOutlineCorners - 2) * quads;
    range.vertexOffset = uint32_t(pool.vertices.size());
    for (uint32_t q = 0; q < quads; ++q) {
        for (uint32_t c = 0; c < kOutlineCorners; ++c) {
            gpu::FieldVertex v{};
            v.position = {float(c), 0.0f, float(q), 0.0f};
            v.normal = {0.0f, 0.0f, 1.0f, 0.0f};
            v.albedo = {1.0f, 1.0f, 1.0f, SURFACE_LEAF};
            pool.vertices.push_back(v);
        }
        // A fan: the outline is convex.
        for (uint32_t c = 1; c + 1 < kOutlineCorners; ++c)
            for (uint32_t i : {0u, c, c + 1}) pool.indices.push_back(kOutlineCorners * q + i);
    }
    return range;
}

} // namespace pf
