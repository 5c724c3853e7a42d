#pragma once
// Assembles a tinygltf::Model for the glTF writers (gltf_export.cpp: a
// PlantAsset; graph_export.cpp: an InstanceGraph); not installed as API.

#include <ostream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "lsystem/mesh/primitive_mesh.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys::export_detail {

class GltfBuilder {
public:
    // One glTF material per entry, in order (so a material index is also the
    // glTF one), and the scene's single root node `plant` (kRoot).
    explicit GltfBuilder(const std::vector<Material>& materials);

    static constexpr int kRoot = 0;

    // A mesh of one primitive; -1 for a mesh without triangles (glTF forbids
    // empty accessors).
    int addMesh(const TriangleMesh& mesh, uint32_t material, std::string name);
    // A mesh with one primitive per material whose entry of `byMaterial` has
    // triangles (entry i drawn with material i); -1 when none has any.
    int addMesh(const std::vector<TriangleMesh>& byMaterial, std::string name);

    // Below `parent` (-1: nowhere yet), placed by `local`; returns its index.
    int addNode(std::string name, int parent, const Frame& local, int mesh = -1);

    // The model as .glb (`binary`) or as .gltf with the buffer embedded.
    void write(std::ostream& out, bool binary);

    tinygltf::Model model;

private:
    // Accessors for the mesh; false when it has no triangles.
    bool addPrimitive(const TriangleMesh& mesh, uint32_t material, tinygltf::Primitive& primitive);
    template <typename T>
    int addAccessor(const std::vector<T>& values, int type, int target, std::vector<double> min = {},
                    std::vector<double> max = {});
};

} // namespace lsys::export_detail
