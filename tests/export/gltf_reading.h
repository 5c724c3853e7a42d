#pragma once
// Exporting into a scratch folder and reading the files back for the tests: glTF through tinygltf, OBJ
// through a reader just big enough to count what the exporter writes.

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

namespace plantfield::test {

// A fixture whose `dir` is a fresh folder named after the running test,
// removed afterwards, for the files a test exports.
class ExportDirTest : public testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    std::filesystem::path dir;
};

// Loads .gltf or .glb; fails the calling test (ADD_FAILURE) on any error.
tinygltf::Model loadGltf(const std::filesystem::path& path);

// Every triangle's corners in scene space: node transforms applied from the
// default scene's roots down; only those of glTF material `material` unless it is -1.
std::vector<glm::vec3> sceneTriangleCorners(const tinygltf::Model& model, int material = -1);

// Whether some point of `points` lies within `tolerance` of `p`.
bool containsPoint(const std::vector<glm::vec3>& points, glm::vec3 p, float tolerance);

struct ObjCounts {
    size_t positions = 0, uvs = 0, normals = 0, triangles = 0;
    std::vector<std::string> objects;   // `o` names, in order
    std::vector<std::string> materials; // `usemtl` names, in order
    std::string mtllib;
    std::vector<glm::vec3> corners; // every face corner's position, as for sceneTriangleCorners
};
ObjCounts readObj(const std::filesystem::path& path);

} // namespace plantfield::test
