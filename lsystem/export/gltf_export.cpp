// glTF 2.0 writer of a PlantAsset: the flat form. The buffer goes into the
// .glb's BIN chunk, or into the .gltf as a base64 data URI so that one file
// is the whole plant.
#include <string>
#include <vector>

#include "lsystem/export/export_detail.h"
#include "lsystem/export/gltf_builder.h"

namespace lsys::export_detail {
namespace {

// `child` in the space of `parent`: what a glTF node below parent's node holds.
Frame relativeTo(const Frame& parent, const Frame& child) {
    const glm::quat inverse = glm::conjugate(parent.rotation);
    return {inverse * (child.position - parent.position), inverse * child.rotation};
}

// The empty joint nodes, nested as Joint::parent says, below the root.
void addSkeleton(GltfBuilder& builder, const PlantAsset& asset, float scale) {
    const auto scaled = [scale](const Frame& rest) { return Frame{rest.position * scale, rest.rotation}; };
    std::vector<int> nodes;
    for (size_t i = 0; i < asset.joints.size(); ++i) {
        const Joint& joint = asset.joints[i];
        const Frame rest = scaled(joint.rest);
        const Frame local = joint.parent < 0 ? rest : relativeTo(scaled(asset.joints[size_t(joint.parent)].rest), rest);
        nodes.push_back(builder.addNode("joint_" + std::to_string(i), -1, local));
    }
    // Linked once all exist: a parent may come after its child in the table.
    for (size_t i = 0; i < asset.joints.size(); ++i) {
        const int32_t parent = asset.joints[i].parent;
        builder.model.nodes[size_t(parent < 0 ? GltfBuilder::kRoot : nodes[size_t(parent)])].children.push_back(
            nodes[i]);
    }
}

} // namespace

void writeGltf(const PlantAsset& asset, const std::vector<TriangleMesh>& byMaterial, std::ostream& out,
               const ExportOptions& options, float scale, bool binary) {
    GltfBuilder builder(asset.materials);
    if (options.skeleton) addSkeleton(builder, asset, scale);
    // One node below the root for each material's mesh that has triangles.
    for (uint32_t m = 0; m < byMaterial.size(); ++m) {
        const std::string name = materialName(asset.materials, m);
        const int mesh = builder.addMesh(byMaterial[m], m, name);
        if (mesh >= 0) builder.addNode(name, GltfBuilder::kRoot, Frame{}, mesh);
    }
    builder.write(out, binary);
}

} // namespace lsys::export_detail
