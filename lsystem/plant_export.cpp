#include "lsystem/plant_export.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "lsystem/export_detail.h"
#include "lsystem/memory_budget.h"
#include "lsystem/output_file.h"

namespace lsys {
namespace export_detail {

std::string materialName(const std::vector<Material>& materials, uint32_t index) {
    const std::string& name = materials[index].name;
    return name.empty() ? "material_" + std::to_string(index) : name;
}

void rethrowNaming(const std::filesystem::path& path) {
    const std::string prefix = "export " + path.string() + ": ";
    try {
        throw;
    } catch (const MemoryBudgetError& error) {
        throw MemoryBudgetError(prefix + error.what());
    } catch (const std::exception& error) {
        throw std::runtime_error(prefix + error.what());
    }
}

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

uint64_t gltfBytes(const MeshSize& meshes, uint64_t nodes, bool binary) {
    return bytesPlus(bytesTimes(meshes.bytes(), binary ? 3 : 6), bytesTimes(nodes, kGltfNodeBytes));
}

uint64_t objBytes(const MeshSize& meshes) { return meshes.bytes(); }

} // namespace export_detail

namespace {

// Indices the writers follow without checking; also rules out joint cycles,
// which would make the glTF node tree a graph.
void checkAsset(const PlantAsset& asset) {
    for (size_t i = 0; i < asset.primitives.size(); ++i) {
        const Primitive& p = asset.primitives[i];
        const auto fail = [&](const std::string& what) {
            throw std::runtime_error("primitive " + std::to_string(i) + ": " + what);
        };
        if (p.material >= asset.materials.size())
            fail("material " + std::to_string(p.material) + " of " + std::to_string(asset.materials.size()));
        if (p.kind == PrimitiveKind::Surface && p.shape >= asset.surfaces.size())
            fail("surface " + std::to_string(p.shape) + " of " + std::to_string(asset.surfaces.size()));
        if (p.kind == PrimitiveKind::Polygon && p.shape >= asset.polygons.size())
            fail("polygon " + std::to_string(p.shape) + " of " + std::to_string(asset.polygons.size()));
        if (p.joint >= int32_t(asset.joints.size()))
            fail("joint " + std::to_string(p.joint) + " of " + std::to_string(asset.joints.size()));
    }
    // Walk up from each joint until a root or a joint already known to reach
    // one; meeting the walk's own path again is a cycle. Linear in joints.
    enum : uint8_t { Unknown, OnPath, ReachesRoot };
    std::vector<uint8_t> state(asset.joints.size(), Unknown);
    std::vector<size_t> path;
    for (size_t i = 0; i < asset.joints.size(); ++i) {
        path.clear();
        for (int32_t j = int32_t(i); j >= 0; j = asset.joints[size_t(j)].parent) {
            if (size_t(j) >= asset.joints.size() || state[size_t(j)] == OnPath)
                throw std::runtime_error("joint " + std::to_string(i) +
                                         ": its parents leave the table or form a cycle");
            if (state[size_t(j)] == ReachesRoot) break;
            state[size_t(j)] = OnPath;
            path.push_back(size_t(j));
        }
        for (size_t j : path) state[j] = ReachesRoot;
    }
}

} // namespace

void exportPlant(const PlantAsset& asset, const std::filesystem::path& path, const ExportOptions& options) {
    using namespace export_detail;
    try {
        const std::string extension = lowercaseExtension(path);
        if (extension != ".gltf" && extension != ".glb" && extension != ".obj")
            throw std::runtime_error("unknown extension '" + extension + "' (expected .gltf, .glb or .obj)");
        checkAsset(asset);
        const MeshSize meshes = bakedMeshSize(asset, options.detail);
        need(options.memory, "export",
             extension == ".obj" ? objBytes(meshes)
                                 : gltfBytes(meshes, options.skeleton ? asset.joints.size() : 0, extension == ".glb"));
        if (extension == ".obj") {
            std::filesystem::path mtlPath = path;
            mtlPath.replace_extension(".mtl");
            OutputFile mtl(mtlPath), obj(path);
            writeObj(asset, obj.stream(), mtl.stream(), mtlPath.filename().string(), options);
            mtl.commit();
            obj.commit();
        } else {
            OutputFile file(path);
            writeGltf(asset, file.stream(), options, extension == ".glb");
            file.commit();
        }
    } catch (const std::exception&) {
        rethrowNaming(path);
    }
}

Bounds bakedBounds(const PlantAsset& asset, SegmentGeometry segments, const MeshDetail& detail) {
    Bounds bounds;
    const auto extend = [&bounds](const TriangleMesh& mesh) {
        for (const glm::vec3& position : mesh.positions) bounds.extend(position);
    };
    const bool tubes = segments == SegmentGeometry::GeneralizedCylinders;
    for (const Primitive& primitive : asset.primitives)
        if (isDrawable(primitive) && !(tubes && primitive.kind == PrimitiveKind::Segment))
            extend(bakedPrimitiveMesh(asset, primitive, detail));
    if (tubes)
        for (const SegmentChain& chain : segmentChains(asset)) extend(generalizedCylinderMesh(asset, chain, detail));
    return bounds;
}

float heightScale(const Bounds& bounds, float height) {
    const float extent = bounds.empty() ? 0.0f : bounds.max.y - bounds.min.y;
    return extent > 0.0f ? height / extent : 0.0f;
}

void scalePlant(PlantAsset& asset, float factor) {
    // Every size a primitive has scales with it: a surface's `length` is its
    // scale, a sphere's radius is startRadius, a polygon's outline is in
    // plant space (its frame only records where it began).
    for (Primitive& p : asset.primitives) {
        p.frame.position *= factor;
        p.length *= factor;
        p.startRadius *= factor;
        p.endRadius *= factor;
    }
    for (PolygonShape& polygon : asset.polygons)
        for (glm::vec3& point : polygon.outline) point *= factor;
    for (Joint& joint : asset.joints) {
        joint.rest.position *= factor;
        joint.length *= factor;
        joint.startRadius *= factor;
        joint.endRadius *= factor;
    }
    if (!asset.bounds.empty()) {
        asset.bounds.min *= factor;
        asset.bounds.max *= factor;
    }
}

} // namespace lsys
