#pragma once
// Shared between the exporters (plant_export.cpp, graph_export.cpp) and the
// per-format writers; not installed as API.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lsystem/export/plant_export.h"

namespace lsys::export_detail {

// The material's name, or "material_<index>" where it has none.
std::string materialName(const std::vector<Material>& materials, uint32_t index);

// Rethrows the exception being handled with "export PATH: " before its
// message: a MemoryBudgetError as one, anything else as std::runtime_error.
[[noreturn]] void rethrowNaming(const std::filesystem::path& path);

// Throws std::runtime_error when a position or normal of `mesh` is NaN or
// infinite: a file that holds one is no model (glTF 2.0 §3.6.2.4 asks for
// finite accessor bounds) and viewers fail on it, so nothing is written.
void requireFinite(const TriangleMesh& mesh);
void requireFinite(const Frame& frame, const std::string& what);

// The extension in lower case, e.g. ".glb": it decides the format.
std::string lowercaseExtension(const std::filesystem::path& path);

// What writing meshes of `meshes` size and `nodes` glTF nodes holds at
// once. Measured peaks (fractal_bush, 262 144 segments): .glb 6.2 kB a
// segment, .gltf 10.5 kB, .obj 1.9 kB. glTF holds the meshes, their copy in
// the model's buffer and tinygltf's copy of it for the BIN chunk (.glb), or
// three base64 copies at 4/3 (the string, the JSON value, the dumped text;
// .gltf); a node with its JSON costs about 1.6 kB. OBJ holds the meshes;
// its text goes out in blocks.
inline constexpr uint64_t kGltfNodeBytes = 2048;
uint64_t gltfBytes(const MeshSize& meshes, uint64_t nodes, bool binary);
uint64_t objBytes(const MeshSize& meshes);

// The writers take the meshes baked, one per material (as meshesByMaterial
// gives them); glTF's skeleton is the asset's, its rest positions times
// `scale` (ExportOptions::height).
void writeGltf(const PlantAsset& asset, const std::vector<TriangleMesh>& meshes, std::ostream& out,
               const ExportOptions& options, float scale, bool binary);
// `mtlFileName` is what the .obj's mtllib line refers to.
void writeObj(const std::vector<Material>& materials, const std::vector<TriangleMesh>& meshes, std::ostream& obj,
              std::ostream& mtl, const std::string& mtlFileName);

} // namespace lsys::export_detail
