#include "lsystem/export/plant_export.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/common/output_file.h"
#include "lsystem/export/export_detail.h"
#include "lsystem/mesh/drawn_mesh.h"

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

// The flat form's meshes, one per material. (The turtle makes every
// material of a surface or polygon two-sided, as the renderer draws them.)
std::vector<TriangleMesh> flatMeshes(const PlantAsset& asset, const ExportOptions& options) {
    if (options.geometry == ExportGeometry::Turtle) return meshesByMaterial(asset, options.segments, options.detail);
    return drawnMeshesByMaterial(asset, drawnScaleOf(asset), exportedDrawnOptions(options.detail.segmentSides));
}

// At most what the turtle's frusta take (a bark tube, a ribbon, a coarser
// sphere all take less) plus each leaf's outline.
MeshSize flatMeshSize(const PlantAsset& asset, const ExportOptions& options) {
    MeshSize size = bakedMeshSize(asset, options.detail);
    if (options.geometry == ExportGeometry::Drawn) {
        const MeshSize outline = leafOutlineSize();
        for (const Primitive& p : asset.primitives)
            if (p.kind == PrimitiveKind::Surface && isDrawable(p)) size.add(outline);
    }
    return size;
}

// Scales the meshes about the origin so their y extent is `height`; returns the scale.
float scaleToHeight(std::vector<TriangleMesh>& meshes, float height) {
    Bounds bounds;
    for (const TriangleMesh& mesh : meshes)
        for (const glm::vec3& p : mesh.positions) bounds.extend(p);
    const float scale = heightScale(bounds, height);
    if (!(scale > 0.0f && std::isfinite(scale)))
        throw std::runtime_error("the plant has no height to scale (its meshes' y extent is 0)");
    for (TriangleMesh& mesh : meshes)
        for (glm::vec3& p : mesh.positions) p *= scale;
    return scale;
}

} // namespace

std::vector<std::filesystem::path> exportedFiles(const std::filesystem::path& path) {
    if (export_detail::lowercaseExtension(path) != ".obj") return {path};
    std::filesystem::path mtlPath = path;
    mtlPath.replace_extension(".mtl");
    return {path, mtlPath};
}

float exportPlant(const PlantAsset& asset, const std::filesystem::path& path, const ExportOptions& options) {
    using namespace export_detail;
    float scale = 1.0f;
    try {
        const std::string extension = lowercaseExtension(path);
        if (extension != ".gltf" && extension != ".glb" && extension != ".obj")
            throw std::runtime_error("unknown extension '" + extension + "' (expected .gltf, .glb or .obj)");
        checkAsset(asset);
        const MeshSize meshes = flatMeshSize(asset, options);
        need(options.memory, "export",
             extension == ".obj" ? objBytes(meshes)
                                 : gltfBytes(meshes, options.skeleton ? asset.joints.size() : 0, extension == ".glb"));
        std::vector<TriangleMesh> flat = flatMeshes(asset, options);
        if (options.height > 0.0f) scale = scaleToHeight(flat, options.height);
        if (extension == ".obj") {
            const std::filesystem::path mtlPath = exportedFiles(path).back();
            OutputFile mtl(mtlPath), obj(path);
            writeObj(asset.materials, flat, obj.stream(), mtl.stream(), mtlPath.filename().string());
            mtl.commit();
            obj.commit();
        } else {
            OutputFile file(path);
            writeGltf(asset, flat, file.stream(), options, scale, extension == ".glb");
            file.commit();
        }
    } catch (const std::exception&) {
        rethrowNaming(path);
    }
    return scale;
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
