#include "lsystem/turtle/turtle_builder.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "lsystem/turtle/surfaces.h"

namespace lsys {

void extendByDisc(Bounds& bounds, glm::vec3 centre, glm::vec3 unitNormal, float radius) {
    // A disc reaches r * sqrt(1 - n_i^2) along axis i.
    const glm::vec3 reach = std::abs(radius) * glm::sqrt(glm::max(glm::vec3(0.0f), 1.0f - unitNormal * unitNormal));
    bounds.extend(centre - reach);
    bounds.extend(centre + reach);
}

Bounds boundsOfPoints(const std::vector<glm::vec3>& points) {
    Bounds bounds;
    for (const glm::vec3& p : points) bounds.extend(p);
    return bounds;
}

const std::vector<Material>& defaultPalette() {
    static const std::vector<Material> palette = {
        {"bark", {0.17f, 0.11f, 0.065f}, false}, {"leaf", {0.20f, 0.45f, 0.12f}, true},
        {"petal", {0.95f, 0.82f, 0.88f}, true},  {"pollen", {0.95f, 0.80f, 0.20f}, false},
        {"fruit", {0.70f, 0.08f, 0.06f}, false}, {"needle", {0.10f, 0.28f, 0.12f}, true},
        {"autumn", {0.85f, 0.45f, 0.10f}, true}, {"deadwood", {0.45f, 0.38f, 0.30f}, false},
    };
    return palette;
}

const SurfaceMesh& surfaceOfLook(const PlantLook& look, const SurfaceLibrary& surfaces, const std::string& name) {
    if (look.surfaces)
        for (const SurfaceMesh& mesh : *look.surfaces)
            if (mesh.name == name) return mesh;
    return surfaces.surface(name);
}

void PlantAssetBuilder::markTwoSided(uint32_t material) {
    if (twoSided_.size() <= material) twoSided_.resize(material + 1);
    twoSided_[material] = true;
}

int32_t PlantAssetBuilder::addSegment(const Frame& base, float length, float startRadius, float endRadius,
                                      uint32_t material, int32_t parentJoint, float stiffness) {
    const int32_t joint = static_cast<int32_t>(asset_.joints.size());
    asset_.joints.push_back({parentJoint, base, length, startRadius, endRadius, stiffness});
    asset_.primitives.push_back({base, PrimitiveKind::Segment, material, joint, 0, length, startRadius, endRadius});
    const glm::vec3 axis = base.rotation * glm::vec3(0.0f, 1.0f, 0.0f);
    extendByDisc(asset_.bounds, base.position, axis, startRadius);
    extendByDisc(asset_.bounds, base.position + axis * length, axis, endRadius);
    return joint;
}

void PlantAssetBuilder::addSphere(const Frame& centre, float radius, uint32_t material, int32_t joint) {
    asset_.primitives.push_back({centre, PrimitiveKind::Sphere, material, joint, 0, 0.0f, radius, radius});
    asset_.bounds.extend(centre.position - glm::vec3(std::abs(radius)));
    asset_.bounds.extend(centre.position + glm::vec3(std::abs(radius)));
}

glm::vec3 PlantAssetBuilder::addSurface(const std::string& name, const Frame& frame, float scale, uint32_t material,
                                        int32_t joint) {
    auto [found, added] = surfaceIndex_.try_emplace(name, static_cast<uint32_t>(asset_.surfaces.size()));
    if (added) {
        try {
            asset_.surfaces.push_back(surfaceOfLook(look_, surfaces_, name));
        } catch (...) {
            surfaceIndex_.erase(found);
            throw;
        }
        surfaceBounds_.push_back(boundsOfPoints(asset_.surfaces.back().positions));
    }
    const uint32_t shape = found->second;
    asset_.primitives.push_back({frame, PrimitiveKind::Surface, material, joint, shape, scale, 0.0f, 0.0f});
    markTwoSided(material);

    // The corners of the surface's local box, scaled and placed, bound it.
    const Bounds& local = surfaceBounds_[shape];
    const glm::vec3 endPoint = asset_.surfaces[shape].endPoint;
    if (local.empty()) return endPoint;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? local.max.x : local.min.x, corner & 2 ? local.max.y : local.min.y,
                          corner & 4 ? local.max.z : local.min.z};
        asset_.bounds.extend(frame.position + frame.rotation * (p * scale));
    }
    return endPoint;
}

void PlantAssetBuilder::addPolygon(const Frame& start, std::vector<glm::vec3> outline, uint32_t material,
                                   int32_t joint) {
    for (const glm::vec3& p : outline) asset_.bounds.extend(p);
    const uint32_t shape = static_cast<uint32_t>(asset_.polygons.size());
    asset_.polygons.push_back({std::move(outline)});
    asset_.primitives.push_back({start, PrimitiveKind::Polygon, material, joint, shape, 0.0f, 0.0f, 0.0f});
    markTwoSided(material);
}

std::vector<Material> materialTable(const PlantLook& look, size_t used, const std::vector<bool>& twoSided) {
    const bool given = look.palette && !look.palette->empty();
    const std::vector<Material>& palette = given ? *look.palette : defaultPalette();
    const size_t count = std::max(palette.size(), used);
    std::vector<Material> materials;
    materials.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        // The default palette repeats; a given one (all 256 of a colour map) has nothing past its end.
        Material material = palette[given ? (i < palette.size() ? i : 0) : i % palette.size()];
        if (i >= palette.size()) material.name.append(1, ' ').append(std::to_string(i));
        if (i < twoSided.size() && twoSided[i]) material.twoSided = true;
        materials.push_back(std::move(material));
    }
    return materials;
}

PlantAsset PlantAssetBuilder::finish() {
    size_t used = 0;
    for (const Primitive& primitive : asset_.primitives) used = std::max<size_t>(used, primitive.material + 1);
    asset_.materials = materialTable(look_, used, twoSided_);
    PlantAsset result = std::move(asset_);
    asset_ = {};
    surfaceIndex_.clear();
    surfaceBounds_.clear();
    twoSided_.clear();
    return result;
}

} // namespace lsys
