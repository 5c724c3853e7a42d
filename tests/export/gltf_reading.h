#pragma once
// Reading exported files back for the tests: glTF through tinygltf, OBJ
// through a reader just big enough to count what the exporter writes.

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <tiny_gltf.h>

namespace plantfield::test {

// Loads .gltf or .glb; fails the calling test (ADD_FAILURE) on any error.
tinygltf::Model loadGltf(const std::filesystem::path& path);

// Every triangle's corners in scene space: node transforms applied from the
// default scene's roots down.
std::vector<glm::vec3> sceneTriangleCorners(const tinygltf::Model& model);

struct ObjCounts {
    size_t positions = 0, uvs = 0, normals = 0, triangles = 0;
    std::vector<std::string> objects;   // `o` names, in order
    std::vector<std::string> materials; // `usemtl` names, in order
    std::string mtllib;
    std::vector<glm::vec3> corners; // every face corner's position, as for sceneTriangleCorners
};
ObjCounts readObj(const std::filesystem::path& path);

}  // namespace plantfield::test
