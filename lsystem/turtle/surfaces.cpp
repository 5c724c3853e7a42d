#include "lsystem/turtle/surfaces.h"

#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>

namespace lsys {

namespace {

// A blade from the origin to (0, 1, 0): `halfWidth(t)` across at height t
// (zero at both ends), `lift(x, t)` out of the plane. One vertex at the base
// and the tip, five across every row between; triangles counter-clockwise
// seen from +Z.
SurfaceMesh blade(const std::string& name, const std::function<float(float)>& halfWidth,
                  const std::function<float(float, float)>& lift, float widest) {
    constexpr int kRows = 8;    // the base and tip are rows 0 and kRows
    constexpr int kColumns = 5; // across each inner row
    SurfaceMesh mesh;
    mesh.name = name;
    auto addVertex = [&](float x, float t) {
        mesh.positions.push_back({x, t, lift(x, t)});
        mesh.uvs.push_back({0.5f + 0.5f * x / widest, t});
    };
    addVertex(0.0f, 0.0f);
    for (int row = 1; row < kRows; ++row) {
        const float t = static_cast<float>(row) / kRows;
        for (int column = 0; column < kColumns; ++column)
            addVertex(halfWidth(t) * (2.0f * column / (kColumns - 1) - 1.0f), t);
    }
    addVertex(0.0f, 1.0f);
    const uint32_t tip = static_cast<uint32_t>(mesh.positions.size() - 1);
    auto at = [](int row, int column) { return static_cast<uint32_t>(1 + (row - 1) * kColumns + column); };
    for (int column = 0; column + 1 < kColumns; ++column) {
        mesh.indices.insert(mesh.indices.end(), {0, at(1, column + 1), at(1, column)});
        mesh.indices.insert(mesh.indices.end(), {tip, at(kRows - 1, column), at(kRows - 1, column + 1)});
        for (int row = 1; row + 1 < kRows; ++row)
            mesh.indices.insert(mesh.indices.end(), {at(row, column), at(row, column + 1), at(row + 1, column + 1),
                                                     at(row, column), at(row + 1, column + 1), at(row + 1, column)});
    }
    // Smooth normals: the area-weighted sum of the faces around each vertex.
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[i]];
        const glm::vec3 face =
            glm::cross(mesh.positions[mesh.indices[i + 1]] - a, mesh.positions[mesh.indices[i + 2]] - a);
        for (size_t k = 0; k < 3; ++k) mesh.normals[mesh.indices[i + k]] += face;
    }
    for (glm::vec3& n : mesh.normals) n = glm::normalize(n);
    return mesh;
}

} // namespace

SurfaceMesh leafSurface() {
    return blade(
        "leaf", [](float t) { return 0.25f * std::sin(std::numbers::pi_v<float> * t); },
        [](float x, float) { return 0.3f * std::abs(x); }, 0.25f);
}

SurfaceMesh petalSurface() {
    return blade(
        "petal", [](float t) { return 0.3f * std::sin(std::numbers::pi_v<float> * t * t); },
        [](float x, float t) { return 0.5f * x * x + 0.15f * t * t; }, 0.3f);
}

SurfaceLibrary::SurfaceLibrary(std::vector<std::filesystem::path> meshDirectories)
    : directories_(std::move(meshDirectories)) {}

const SurfaceMesh& SurfaceLibrary::surface(const std::string& name) const {
    std::lock_guard lock(mutex_);
    if (auto found = loaded_.find(name); found != loaded_.end()) return found->second;
    if (name == "leaf") return loaded_.emplace(name, leafSurface()).first->second;
    if (name == "petal") return loaded_.emplace(name, petalSurface()).first->second;
    std::string tried;
    for (const std::filesystem::path& directory : directories_) {
        for (const char* extension : {".gltf", ".glb"}) {
            const std::filesystem::path file = directory / (name + extension);
            if (std::filesystem::is_regular_file(file))
                return loaded_.emplace(name, loadSurfaceFile(file, name)).first->second;
            tried += (tried.empty() ? "" : ", ") + file.string();
        }
    }
    throw SurfaceError("unknown surface ~" + name + ": not built in (leaf, petal) and no mesh file " +
                       (tried.empty() ? "(no mesh directories to search)" : "at " + tried));
}

std::vector<std::filesystem::path> meshDirectoriesFor(const std::filesystem::path& plantFile) {
    std::vector<std::filesystem::path> directories;
    std::filesystem::path directory = std::filesystem::absolute(plantFile).parent_path();
    while (true) {
        if (std::filesystem::is_directory(directory / "meshes")) directories.push_back(directory / "meshes");
        if (directory == directory.parent_path()) return directories;
        directory = directory.parent_path();
    }
}

} // namespace lsys
