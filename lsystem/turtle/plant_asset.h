#pragma once
// A plant once interpreted: the records a renderer uploads and an exporter
// writes. The turtle produces one directly from a derived string; flattening
// an InstanceGraph must produce the same records (docs/INSTANCING.md).
//
// Plant space is the turtle's space, y up: the turtle starts at the origin
// heading +Y with left -X and up +Z. A Frame's rotation maps local axes to
// plant space as local +Y → heading H, local -X → left L, local +Z → up U, so
// the start frame is the identity. Its materials and surfaces are
// lsystem/language/plant_look.h's, which the grammar's look names too.

#include <cstdint>
#include <limits>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "lsystem/language/plant_look.h"

namespace lsys {

struct Frame {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};

    friend bool operator==(const Frame&, const Frame&) = default;
};

enum class PrimitiveKind : uint8_t {
    Segment, // cone frustum along local +Y: `length`, radii startRadius → endRadius
    Sphere,  // sphere of radius startRadius centred on the frame (@O)
    Surface, // PlantAsset::surfaces[shape] scaled uniformly by `length` (~leaf, ~petal, glTF meshes)
    Polygon, // PlantAsset::polygons[shape]; its vertices are in plant space, the frame is where it began
};

struct Primitive {
    Frame frame;
    PrimitiveKind kind = PrimitiveKind::Segment;
    uint32_t material = 0;
    int32_t joint = -1; // the joint it moves with; a segment is its own joint; -1: the plant's base
    uint32_t shape = 0;
    float length = 0.0f;
    float startRadius = 0.0f;
    float endRadius = 0.0f;

    // Field by field: comparing the bytes would compare the padding after `kind`.
    friend bool operator==(const Primitive&, const Primitive&) = default;
};

// One drawn segment of the skeleton in its rest pose (Crankshaw 2020's joints).
struct Joint {
    int32_t parent = -1; // joint this one grows on; -1 for a root
    Frame rest;          // plant-space frame at the segment's base
    float length = 0.0f;
    float startRadius = 0.0f;
    float endRadius = 0.0f;
    float stiffness = 0.0f; // N·m/rad from @K(k) or Crankshaw's F(l, k); 0: from beam theory when simulated
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& b) {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
};

// A `{ . . . }` polygon: its outline, in plant space, as the turtle traced it.
struct PolygonShape {
    std::vector<glm::vec3> outline;
};

struct PlantAsset {
    std::vector<Primitive> primitives;
    std::vector<Material> materials; // every Primitive::material indexes this table
    std::vector<Joint> joints;
    std::vector<SurfaceMesh> surfaces;
    std::vector<PolygonShape> polygons;
    Bounds bounds;
};

} // namespace lsys
