// glTF 2.0 writer. The buffer goes into the .glb's BIN chunk, or into the
// .gltf as a base64 data URI so that one file is the whole plant.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "lsystem/export_detail.h"

namespace lsys::export_detail {
namespace {

// `child` in the space of `parent`: what a glTF node below parent's node holds.
Frame relativeTo(const Frame& parent, const Frame& child) {
    const glm::quat inverse = glm::conjugate(parent.rotation);
    return {inverse * (child.position - parent.position), inverse * child.rotation};
}

class GltfBuilder {
public:
    explicit GltfBuilder(const PlantAsset& asset) {
        model.asset.version = "2.0";
        model.asset.generator = "plantfield lsystem exporter";
        model.buffers.emplace_back();
        for (uint32_t i = 0; i < asset.materials.size(); ++i) {
            const Material& source = asset.materials[i];
            tinygltf::Material& material = model.materials.emplace_back();
            material.name = materialName(asset, i);
            material.pbrMetallicRoughness.baseColorFactor = {source.albedo.r, source.albedo.g, source.albedo.b, 1.0};
            // Bark and leaves are dielectric and matte; glTF's default is metal.
            material.pbrMetallicRoughness.metallicFactor = 0.0;
            material.pbrMetallicRoughness.roughnessFactor = 1.0;
            material.doubleSided = source.twoSided;
        }
        model.scenes.emplace_back().nodes = {addNode("plant", -1, Frame{})};
        model.defaultScene = 0;
    }

    static constexpr int kRoot = 0;

    // The mesh's index, or -1 for a mesh without triangles (glTF forbids empty accessors).
    int addMesh(const TriangleMesh& mesh, uint32_t material, std::string name) {
        if (mesh.indices.empty()) return -1;
        tinygltf::Primitive primitive;
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
        tinygltf::Mesh& added = model.meshes.emplace_back();
        added.name = std::move(name);
        added.primitives.push_back(std::move(primitive));
        return int(model.meshes.size() - 1);
    }

    int addNode(std::string name, int parent, const Frame& local, glm::vec3 scale = glm::vec3(1.0f), int mesh = -1) {
        tinygltf::Node node;
        node.name = std::move(name);
        node.mesh = mesh;
        if (local.position != glm::vec3(0.0f)) node.translation = {local.position.x, local.position.y, local.position.z};
        const glm::dquat rotation = glm::normalize(glm::dquat(local.rotation));
        if (rotation != glm::dquat(1.0, 0.0, 0.0, 0.0)) node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        if (scale != glm::vec3(1.0f)) node.scale = {scale.x, scale.y, scale.z};
        model.nodes.push_back(std::move(node));
        const int index = int(model.nodes.size() - 1);
        if (parent >= 0) model.nodes[size_t(parent)].children.push_back(index);
        return index;
    }

    tinygltf::Model model;

private:
    template <typename T>
    int addAccessor(const std::vector<T>& values, int type, int target, std::vector<double> min = {},
                    std::vector<double> max = {}) {
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
        accessor.componentType = std::is_same_v<T, uint32_t> ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = type;
        accessor.count = values.size();
        accessor.minValues = std::move(min);
        accessor.maxValues = std::move(max);
        return int(model.accessors.size() - 1);
    }
};

// The empty joint nodes, nested as Joint::parent says, below the root.
std::vector<int> addSkeleton(GltfBuilder& builder, const PlantAsset& asset) {
    std::vector<int> nodes;
    for (size_t i = 0; i < asset.joints.size(); ++i) {
        const Joint& joint = asset.joints[i];
        const Frame local = joint.parent < 0 ? joint.rest : relativeTo(asset.joints[size_t(joint.parent)].rest, joint.rest);
        nodes.push_back(builder.addNode("joint_" + std::to_string(i), -1, local));
    }
    // Linked once all exist: a parent may come after its child in the table.
    for (size_t i = 0; i < asset.joints.size(); ++i) {
        const int32_t parent = asset.joints[i].parent;
        builder.model.nodes[size_t(parent < 0 ? GltfBuilder::kRoot : nodes[size_t(parent)])].children.push_back(nodes[i]);
    }
    return nodes;
}

// What makes two primitives share one glTF mesh.
struct ShapeKey {
    PrimitiveKind kind;
    uint32_t material;
    uint32_t shape;
    float startRadius; // a segment's radii divided by the larger one
    float endRadius;
    auto operator<=>(const ShapeKey&) const = default;
};

const char* kindName(PrimitiveKind kind) {
    switch (kind) {
    case PrimitiveKind::Segment: return "segment";
    case PrimitiveKind::Sphere: return "sphere";
    case PrimitiveKind::Surface: return "surface";
    case PrimitiveKind::Polygon: return "polygon";
    }
    return "primitive";
}

// e.g. "segment_1_0.800049_bark" (its radii), "sphere_bark", "surface_leaf_bark",
// "polygon_3_bark".
std::string meshName(const PlantAsset& asset, const ShapeKey& key) {
    std::string name = kindName(key.kind);
    const auto number = [](float value) {
        std::string text = std::to_string(value);
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
        return text;
    };
    if (key.kind == PrimitiveKind::Segment) name += "_" + number(key.startRadius) + "_" + number(key.endRadius);
    if (key.kind == PrimitiveKind::Surface) name += "_" + asset.surfaces[key.shape].name;
    if (key.kind == PrimitiveKind::Polygon) name += "_" + std::to_string(key.shape);
    return name + "_" + materialName(asset, key.material);
}

// One node per primitive, its mesh shared with every primitive of the same
// shape: a unit frustum per radius ratio (scaled by radius in x and z and by
// length in y), a unit sphere, each surface, each polygon (in plant space).
// Segments are left out when they are drawn as generalised cylinders.
void addInstancedPrimitives(GltfBuilder& builder, const PlantAsset& asset, const ExportOptions& options,
                            const std::vector<int>& jointNodes) {
    std::map<ShapeKey, int> meshes;
    const bool tubes = options.segments == SegmentGeometry::GeneralizedCylinders;
    for (size_t i = 0; i < asset.primitives.size(); ++i) {
        const Primitive& p = asset.primitives[i];
        if (!isDrawable(p) || (tubes && p.kind == PrimitiveKind::Segment)) continue;
        ShapeKey key{p.kind, p.material, 0, 0.0f, 0.0f};
        Frame frame = p.frame;
        glm::vec3 scale(1.0f);
        switch (p.kind) {
        case PrimitiveKind::Segment: {
            // Ratios rounded to 1/4096 (an error under 0.025 % of the radius),
            // so that widths scaled by the same factor share one mesh even
            // when float rounding differs in the last bits.
            const float radius = std::max(p.startRadius, p.endRadius);
            key.startRadius = std::round(4096.0f * p.startRadius / radius) / 4096.0f;
            key.endRadius = std::round(4096.0f * p.endRadius / radius) / 4096.0f;
            scale = {radius, p.length, radius};
            break;
        }
        case PrimitiveKind::Sphere: scale = glm::vec3(p.startRadius); break;
        case PrimitiveKind::Surface:
            key.shape = p.shape;
            scale = glm::vec3(p.length);
            break;
        case PrimitiveKind::Polygon:
            key.shape = p.shape;
            frame = Frame{};
            break;
        }
        auto [found, isNew] = meshes.try_emplace(key, -1);
        if (isNew) {
            TriangleMesh mesh;
            switch (p.kind) {
            case PrimitiveKind::Segment: mesh = segmentMesh(1.0f, key.startRadius, key.endRadius, options.detail); break;
            case PrimitiveKind::Sphere: mesh = sphereMesh(1.0f, options.detail); break;
            case PrimitiveKind::Surface: mesh = surfaceMesh(asset.surfaces[p.shape]); break;
            case PrimitiveKind::Polygon: mesh = polygonMesh(asset.polygons[p.shape].outline); break;
            }
            found->second = builder.addMesh(mesh, p.material, meshName(asset, key));
        }
        if (found->second < 0) continue;
        const bool onJoint = p.joint >= 0 && !jointNodes.empty();
        const int parent = onJoint ? jointNodes[size_t(p.joint)] : GltfBuilder::kRoot;
        const Frame local = onJoint ? relativeTo(asset.joints[size_t(p.joint)].rest, frame) : frame;
        builder.addNode(std::string(kindName(p.kind)) + "_" + std::to_string(i), parent, local, scale, found->second);
    }
}

// One node below the root for each material's mesh that has triangles.
void addBakedMeshes(GltfBuilder& builder, const PlantAsset& asset, const std::vector<TriangleMesh>& byMaterial,
                    const std::string& prefix) {
    for (uint32_t m = 0; m < byMaterial.size(); ++m) {
        const std::string name = prefix + materialName(asset, m);
        const int mesh = builder.addMesh(byMaterial[m], m, name);
        if (mesh >= 0) builder.addNode(name, GltfBuilder::kRoot, Frame{}, glm::vec3(1.0f), mesh);
    }
}

}  // namespace

void writeGltf(const PlantAsset& asset, std::ostream& out, const ExportOptions& options, bool binary) {
    GltfBuilder builder(asset);
    const std::vector<int> jointNodes = options.skeleton ? addSkeleton(builder, asset) : std::vector<int>{};
    if (options.form == ExportForm::Flat) {
        addBakedMeshes(builder, asset, meshesByMaterial(asset, options.segments, options.detail), "");
    } else {
        addInstancedPrimitives(builder, asset, options, jointNodes);
        // A bent tube is not shareable: the chains are baked per material.
        if (options.segments == SegmentGeometry::GeneralizedCylinders)
            addBakedMeshes(builder, asset, generalizedCylindersByMaterial(asset, options.detail), "stems_");
    }
    if (builder.model.buffers[0].data.empty()) builder.model.buffers.clear(); // glTF forbids an empty buffer
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&builder.model, out, false, binary) || !out)
        throw std::runtime_error("writing the glTF stream failed");
}

}  // namespace lsys::export_detail
