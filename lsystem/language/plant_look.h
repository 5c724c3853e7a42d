#pragma once
// What a plant's files say about its look besides its productions: the
// meaning of its material indices and surfaces of its own (a vlab object's
// colour map and surface files, lsystem/vlab/object.h). The Grammar carries
// a PlantLook in its TurtleStyle; the turtle draws with it
// (lsystem/turtle/turtle_builder.h), and a PlantAsset
// (lsystem/turtle/plant_asset.h) holds the materials and surfaces it drew.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lsys {

// A predefined surface in its own space (local axes as for a Frame).
struct SurfaceMesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
    // Where the turtle stands after drawing it at scale 1 (cpfg's END POINT
    // of a .s file); the origin for the built-in and glTF surfaces.
    glm::vec3 endPoint{0.0f};
};

// What a material index (`;(i)`, `'`) means when drawn or exported.
struct Material {
    std::string name;
    glm::vec3 albedo{0.5f};
    bool twoSided = false; // leaves and petals are seen from both sides
};

// What a plant brings besides its grammar (a vlab object's colour map and
// surface files): the meaning of its material indices, and surfaces that ~
// finds before the SurfaceLibrary's. Null: the default palette
// (lsystem/turtle/turtle_builder.h) and the library's surfaces only.
struct PlantLook {
    std::shared_ptr<const std::vector<Material>> palette;
    std::shared_ptr<const std::vector<SurfaceMesh>> surfaces;
};

} // namespace lsys
