#pragma once
// Shared between the exporters (plant_export.cpp, graph_export.cpp) and the
// per-format writers; not installed as API.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lsystem/plant_export.h"

namespace lsys::export_detail {

// The material's name, or "material_<index>" where it has none.
std::string materialName(const std::vector<Material>& materials, uint32_t index);

// The extension in lower case, e.g. ".glb": it decides the format.
std::string lowercaseExtension(const std::filesystem::path& path);

void writeGltf(const PlantAsset& asset, std::ostream& out, const ExportOptions& options, bool binary);
// `mtlFileName` is what the .obj's mtllib line refers to.
void writeObj(const PlantAsset& asset, std::ostream& obj, std::ostream& mtl, const std::string& mtlFileName,
              const ExportOptions& options);

} // namespace lsys::export_detail
