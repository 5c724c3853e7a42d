#pragma once
// Rays and hits for tracing a plant (docs/RAYTRACING.md): the same records
// whether the plant is traced as a flat PlantAsset or through an
// InstanceGraph's hierarchy.

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// The points origin + t·direction for t in [tMin, tMax]. `direction` need
// not be unit length: t is in its units, and stays the same parameter in
// every frame the ray is carried into (frames are rigid).
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();
};

// What a ray hit: its parameter, which primitive (its kind and material, and
// its index among the traced plant's primitives: PlantAsset::primitives or
// InstanceGraph::primitives), and the unit geometric normal there in the
// space of the ray that was traced: outward on segments and spheres, on the
// counter-clockwise side of a triangle; never flipped towards the ray.
struct Hit {
    float t = std::numeric_limits<float>::infinity();
    PrimitiveKind kind = PrimitiveKind::Segment;
    uint32_t material = 0;
    uint32_t primitive = 0;
    glm::vec3 normal{0.0f};
};

// Closest: the nearest hit in [tMin, tMax]. Any: whichever hit is found
// first, for shadow rays that only ask whether something is in the way.
enum class HitQuery : uint8_t { Closest, Any };

} // namespace lsys
