#include "gltf_reading.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <gtest/gtest.h>

namespace plantfield::test {
namespace {

template <typename T>
std::vector<T> accessorValues(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& accessor = model.accessors.at(size_t(index));
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
    const size_t stride = view.byteStride ? view.byteStride : sizeof(T);
    const unsigned char* data =
        model.buffers.at(size_t(view.buffer)).data.data() + view.byteOffset + accessor.byteOffset;
    std::vector<T> values(accessor.count);
    for (size_t i = 0; i < accessor.count; ++i) std::memcpy(&values[i], data + i * stride, sizeof(T));
    return values;
}

glm::mat4 localMatrix(const tinygltf::Node& node) {
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3)
        m[3] = glm::vec4(node.translation[0], node.translation[1], node.translation[2], 1.0f);
    if (node.rotation.size() == 4)
        m = m * glm::mat4_cast(glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                                         float(node.rotation[2])));
    if (node.scale.size() == 3)
        m = m * glm::scale(glm::mat4(1.0f), glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

void collect(const tinygltf::Model& model, int nodeIndex, const glm::mat4& parent, int material,
             std::vector<glm::vec3>& corners) {
    const tinygltf::Node& node = model.nodes.at(size_t(nodeIndex));
    const glm::mat4 world = parent * localMatrix(node);
    if (node.mesh >= 0) {
        for (const tinygltf::Primitive& primitive : model.meshes.at(size_t(node.mesh)).primitives) {
            if (material >= 0 && primitive.material != material) continue;
            const auto positions = accessorValues<glm::vec3>(model, primitive.attributes.at("POSITION"));
            for (uint32_t i : accessorValues<uint32_t>(model, primitive.indices))
                corners.push_back(glm::vec3(world * glm::vec4(positions.at(i), 1.0f)));
        }
    }
    for (int child : node.children) collect(model, child, world, material, corners);
}

} // namespace

void ExportDirTest::SetUp() {
    dir =
        std::filesystem::temp_directory_path() /
        ("plantfield_export_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) +
         "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
}

void ExportDirTest::TearDown() { std::filesystem::remove_all(dir); }

tinygltf::Model loadGltf(const std::filesystem::path& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                                               : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
    if (!ok || !error.empty()) ADD_FAILURE() << "loading " << path << ": " << error;
    return model;
}

std::vector<glm::vec3> sceneTriangleCorners(const tinygltf::Model& model, int material) {
    std::vector<glm::vec3> corners;
    for (int root : model.scenes.at(size_t(std::max(model.defaultScene, 0))).nodes)
        collect(model, root, glm::mat4(1.0f), material, corners);
    return corners;
}

bool containsPoint(const std::vector<glm::vec3>& points, glm::vec3 p, float tolerance) {
    return std::any_of(points.begin(), points.end(), [&](glm::vec3 q) { return glm::distance(p, q) <= tolerance; });
}

ObjCounts readObj(const std::filesystem::path& path) {
    ObjCounts counts;
    std::vector<glm::vec3> positions;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        std::string tag;
        fields >> tag;
        if (tag == "v") {
            glm::vec3& p = positions.emplace_back();
            fields >> p.x >> p.y >> p.z;
        } else if (tag == "vt")
            ++counts.uvs;
        else if (tag == "vn")
            ++counts.normals;
        else if (tag == "o")
            counts.objects.emplace_back(line.substr(2));
        else if (tag == "usemtl")
            counts.materials.emplace_back(line.substr(7));
        else if (tag == "mtllib")
            counts.mtllib = line.substr(7);
        else if (tag == "f") {
            ++counts.triangles;
            for (std::string corner; fields >> corner;) counts.corners.push_back(positions.at(std::stoul(corner) - 1));
        }
    }
    counts.positions = positions.size();
    return counts;
}

} // namespace plantfield::test
