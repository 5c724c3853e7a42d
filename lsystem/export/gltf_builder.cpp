#include "lsystem/export/gltf_builder.h"

#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "lsystem/export/export_detail.h"

namespace lsys::export_detail {

GltfBuilder::GltfBuilder(const std::vector<Material>& materials) {
    model.asset.version = "2.0";
    model.asset.generator = "plantfield lsystem exporter";
    model.buffers.emplace_back();
    for (uint32_t i = 0; i < materials.size(); ++i) {
        const Material& source = materials[i];
        tinygltf::Material& material = model.materials.emplace_back();
        material.name = materialName(materials, i);
        material.pbrMetallicRoughness.baseColorFactor = {source.albedo.r, source.albedo.g, source.albedo.b, 1.0};
        // Bark and leaves are dielectric and matte; glTF's default is metal.
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        material.doubleSided = source.twoSided;
    }
    model.scenes.emplace_back().nodes = {addNode("plant", -1, Frame{})};
    model.defaultScene = 0;
}

bool GltfBuilder::addPrimitive(const TriangleMesh& mesh, uint32_t material, tinygltf::Primitive& primitive) {
    if (mesh.indices.empty()) return false;
    requireFinite(mesh);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = int(material);
    glm::vec3 low = mesh.positions.front(), high = low;
    for (const glm::vec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    primitive.attributes["POSITION"] = addAccessor(mesh.positions, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER,
                                                   {low.x, low.y, low.z}, {high.x, high.y, high.z});
    primitive.attributes["NORMAL"] = addAccessor(mesh.normals, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["TEXCOORD_0"] = addAccessor(mesh.uvs, TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.indices = addAccessor(mesh.indices, TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return true;
}

int GltfBuilder::addMesh(const TriangleMesh& mesh, uint32_t material, std::string name) {
    tinygltf::Mesh added;
    if (!addPrimitive(mesh, material, added.primitives.emplace_back())) return -1;
    added.name = std::move(name);
    model.meshes.push_back(std::move(added));
    return int(model.meshes.size() - 1);
}

int GltfBuilder::addMesh(const std::vector<TriangleMesh>& byMaterial, std::string name) {
    tinygltf::Mesh added;
    for (uint32_t m = 0; m < byMaterial.size(); ++m) {
        tinygltf::Primitive primitive;
        if (addPrimitive(byMaterial[m], m, primitive)) added.primitives.push_back(std::move(primitive));
    }
    if (added.primitives.empty()) return -1;
    added.name = std::move(name);
    model.meshes.push_back(std::move(added));
    return int(model.meshes.size() - 1);
}

int GltfBuilder::addNode(std::string name, int parent, const Frame& local, int mesh) {
    requireFinite(local, "node '" + name + "'");
    tinygltf::Node node;
    node.name = std::move(name);
    node.mesh = mesh;
    if (local.position != glm::vec3(0.0f)) node.translation = {local.position.x, local.position.y, local.position.z};
    const glm::dquat rotation = glm::normalize(glm::dquat(local.rotation));
    if (rotation != glm::dquat(1.0, 0.0, 0.0, 0.0)) node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
    model.nodes.push_back(std::move(node));
    const int index = int(model.nodes.size() - 1);
    if (parent >= 0) model.nodes[size_t(parent)].children.push_back(index);
    return index;
}

void GltfBuilder::write(std::ostream& out, bool binary) {
    if (model.buffers[0].data.empty()) model.buffers.clear(); // glTF forbids an empty buffer
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, binary) || !out)
        throw std::runtime_error("writing the glTF stream failed");
}

template <typename T>
int GltfBuilder::addAccessor(const std::vector<T>& values, int type, int target, std::vector<double> min,
                             std::vector<double> max) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView& view = model.bufferViews.emplace_back();
    view.buffer = 0;
    view.byteOffset = data.size(); // every element is 4-byte aligned, so every view is
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);

    tinygltf::Accessor& accessor = model.accessors.emplace_back();
    accessor.bufferView = int(model.bufferViews.size() - 1);
    accessor.componentType =
        std::is_same_v<T, uint32_t> ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = values.size();
    accessor.minValues = std::move(min);
    accessor.maxValues = std::move(max);
    return int(model.accessors.size() - 1);
}

} // namespace lsys::export_detail
