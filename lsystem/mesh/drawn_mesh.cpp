// The plant as the field draws it (docs/FIELD.md "Plant models (meshes and
// LODs)", docs/EXPORT.md "The drawn form").
#include "lsystem/mesh/drawn_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shaders/shared/leaf_outline.h"

namespace lsys {
namespace {

// LOD1 keeps every kLeafStride-th leaf card, each enlarged by √kLeafStride so
// the foliage covers the same area.
constexpr uint32_t kLeafStride = 4;
// LOD1 drops bark thinner than this fraction of the trunk's radius.
constexpr float kTwigFraction = 0.06f;
// LOD1 merges up to this many foliage segments of a chain into one ribbon
// quad, and keeps every kRibbonStride-th foliage chain kRibbonStride times as
// wide (needle sprays and grass blades keep their area).
constexpr size_t kRibbonRun = 4;
constexpr uint32_t kRibbonStride = 3;
// LOD1 thins leaf cards and foliage chains only where a plant has many: one
// kept in kLeafStride (kRibbonStride) at most, and at least one in
// kMinThinned kept whole — a herb of six leaves keeps all six, where thinned
// to two enlarged ones it would read as another plant.
constexpr uint32_t kMinThinned = 16;
// Foliage ribbons are at least this fraction of the plant's largest extent
// wide: a grass blade of radius 0 must still cover pixels.
constexpr float kMinRibbonWidth = 0.004f;

// Everything that decides how one LOD is baked.
struct LodRecipe {
    bool reduced = false;
    DrawnScale scale;
    DrawnOptions options;
};

// Primitive::joint of the plant's base (-1) moves with the first joint: at
// the base it barely moves, and the skeleton needs no extra root entry.
uint32_t jointOf(int32_t joint) { return joint < 0 ? 0u : uint32_t(joint); }

void appendTriangleMesh(DrawnMesh& out, const TriangleMesh& mesh, uint32_t material, SurfaceKind kind,
                        const std::vector<uint32_t>& joints) {
    const uint32_t base = uint32_t(out.vertices.size());
    for (uint32_t i = 0; i < mesh.vertexCount(); ++i)
        out.vertices.push_back({mesh.positions[i], mesh.normals[i], mesh.uvs[i], material, kind, joints[i]});
    for (uint32_t index : mesh.indices) out.indices.push_back(base + index);
}

// A quad a b c d (counter-clockwise seen from `normal`), two triangles.
void appendQuad(DrawnMesh& out, const std::array<DrawnVertex, 4>& corners) {
    const uint32_t base = uint32_t(out.vertices.size());
    out.vertices.insert(out.vertices.end(), corners.begin(), corners.end());
    out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

glm::vec3 axisOf(const Frame& frame, glm::vec3 local) { return frame.rotation * local; }

bool isFoliageSegment(const PlantAsset& asset, const Primitive& primitive) {
    return primitive.kind == PrimitiveKind::Segment && asset.materials.at(primitive.material).twoSided;
}

float largestExtent(const Bounds& bounds) {
    if (bounds.empty()) return 1.0f;
    const glm::vec3 size = bounds.max - bounds.min;
    return std::max({size.x, size.y, size.z, 1e-3f});
}

float trunkRadiusOf(const PlantAsset& asset) {
    float radius = 0.0f;
    for (const Primitive& p : asset.primitives)
        if (p.kind == PrimitiveKind::Segment && !isFoliageSegment(asset, p))
            radius = std::max({radius, p.startRadius, p.endRadius});
    return radius;
}

// Ring sides of a bark tube from its thickness relative to the trunk: the
// trunk is round up close, twigs need only a few sides (with the trunk's 8:
// 8, 6, 4, 3 at full detail, 4 and 3 reduced).
uint32_t barkSides(const LodRecipe& recipe, float radius) {
    const float trunk = recipe.scale.trunkRadius;
    const float relative = trunk > 0.0f ? radius / trunk : 1.0f;
    const uint32_t sides = std::max(recipe.options.trunkSides, 3u);
    const uint32_t half = std::max(sides / 2, 3u), threeQuarters = std::max(sides * 3 / 4, 3u);
    if (recipe.reduced) return relative >= 0.25f ? half : 3u;
    if (relative >= 0.25f) return sides;
    if (relative >= 0.06f) return threeQuarters;
    return relative >= 0.02f ? half : 3u;
}

// The chain without its segments thinner than the LOD keeps (radii shrink
// toward the tip, so that is a tip part).
SegmentChain keptPart(const PlantAsset& asset, const SegmentChain& chain, const LodRecipe& recipe) {
    if (!recipe.reduced) return chain;
    SegmentChain kept;
    for (uint32_t p : chain.primitives) {
        const Primitive& segment = asset.primitives[p];
        if (std::max(segment.startRadius, segment.endRadius) < kTwigFraction * recipe.scale.trunkRadius) break;
        kept.primitives.push_back(p);
    }
    return kept;
}

// One generalised cylinder per chain of bark segments; each ring moves with
// the segment whose tip it is (the base ring with the first segment).
void bakeBarkChain(DrawnMesh& out, const PlantAsset& asset, const SegmentChain& chain, const LodRecipe& recipe) {
    if (chain.primitives.empty()) return;
    const Primitive& first = asset.primitives[chain.primitives.front()];
    MeshDetail detail;
    detail.segmentSides = barkSides(recipe, first.startRadius);
    detail.segmentCaps = !recipe.reduced;
    const TriangleMesh mesh = generalizedCylinderMesh(asset, chain, detail);
    const uint32_t ringVertices = detail.segmentSides + 1;
    const size_t rings = chain.primitives.size() + 1;
    std::vector<uint32_t> joints(mesh.vertexCount());
    for (uint32_t i = 0; i < mesh.vertexCount(); ++i) {
        const size_t ring = i / ringVertices;
        // Ring r is the tip of segment r-1; cap vertices follow the rings: base cap, then tip cap.
        const size_t segment = ring < rings ? (ring == 0 ? 0 : ring - 1) : (ring == rings ? 0 : rings - 2);
        joints[i] = jointOf(asset.primitives[chain.primitives[segment]].joint);
    }
    appendTriangleMesh(out, mesh, first.material, SurfaceKind::Bark, joints);
}

void bakeSphere(DrawnMesh& out, const PlantAsset& asset, const Primitive& sphere, const LodRecipe& recipe) {
    MeshDetail detail;
    detail.sphereSlices = recipe.reduced ? 4 : 8;
    detail.sphereStacks = recipe.reduced ? 3 : 6;
    const TriangleMesh mesh = bakedPrimitiveMesh(asset, sphere, detail);
    appendTriangleMesh(out, mesh, sphere.material, SurfaceKind::Bark,
                       std::vector<uint32_t>(mesh.vertexCount(), jointOf(sphere.joint)));
}

// Local x and y extent of a surface: the card spans it.
struct SurfaceExtent {
    glm::vec2 min{0.0f}, max{0.0f};
};

SurfaceExtent extentOf(const SurfaceMesh& surface) {
    SurfaceExtent extent{glm::vec2(std::numeric_limits<float>::max()), glm::vec2(std::numeric_limits<float>::lowest())};
    for (const glm::vec3& p : surface.positions) {
        extent.min = glm::min(extent.min, glm::vec2(p));
        extent.max = glm::max(extent.max, glm::vec2(p));
    }
    if (surface.positions.empty()) extent = {};
    return extent;
}

glm::vec3 onCard(glm::vec3 origin, glm::vec3 across, glm::vec3 along, glm::vec2 uv) {
    return origin + uv.x * across + uv.y * along;
}

// A leaf card: the surface's x-y extent on the surface's plane, petiole
// (v = 0) at its local -y end. `enlarge` grows it about the petiole's
// midpoint. As a quad, or as the mesh of its leaf outline.
void bakeLeafCard(DrawnMesh& out, const Primitive& surface, const SurfaceExtent& extent, float enlarge,
                  LeafCards leaves) {
    const float scale = surface.length;
    const glm::vec3 x = axisOf(surface.frame, {1, 0, 0}), y = axisOf(surface.frame, {0, 1, 0});
    const glm::vec3 normal = axisOf(surface.frame, {0, 0, 1});
    const glm::vec3 origin =
        surface.frame.position + scale * (x * 0.5f * (extent.min.x + extent.max.x) + y * extent.min.y);
    const glm::vec3 across = scale * enlarge * x * (extent.max.x - extent.min.x);
    const glm::vec3 along = scale * enlarge * y * (extent.max.y - extent.min.y);
    const uint32_t joint = jointOf(surface.joint);
    const auto vertex = [&](glm::vec3 position, glm::vec2 uv) {
        return DrawnVertex{position, normal, uv, surface.material, SurfaceKind::LeafCard, joint};
    };
    if (leaves == LeafCards::Quads) {
        const auto corner = [&](float u, float v) { return vertex(origin + (u - 0.5f) * across + v * along, {u, v}); };
        appendQuad(out, {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)});
        return;
    }
    const LeafOutline& outline = leafOutline();
    const uint32_t base = uint32_t(out.vertices.size());
    for (const glm::vec2& uv : outline.uvs)
        out.vertices.push_back(vertex(onCard(origin - 0.5f * across, across, along, uv), uv));
    for (uint32_t index : outline.indices) out.indices.push_back(base + index);
}

// A flat ribbon from `base` to `tip` across the frame's local x, facing its
// local z; u across, v along.
void bakeRibbon(DrawnMesh& out, const Frame& frame, glm::vec3 base, glm::vec3 tip, float baseWidth, float tipWidth,
                uint32_t material, uint32_t baseJoint, uint32_t tipJoint) {
    const glm::vec3 across = axisOf(frame, {1, 0, 0}), normal = axisOf(frame, {0, 0, 1});
    const auto vertex = [&](glm::vec3 position, glm::vec2 uv, uint32_t joint) {
        return DrawnVertex{position, normal, uv, material, SurfaceKind::Blade, joint};
    };
    appendQuad(out, {vertex(base - 0.5f * baseWidth * across, {0, 0}, baseJoint),
                     vertex(base + 0.5f * baseWidth * across, {1, 0}, baseJoint),
                     vertex(tip + 0.5f * tipWidth * across, {1, 1}, tipJoint),
                     vertex(tip - 0.5f * tipWidth * across, {0, 1}, tipJoint)});
}

glm::vec3 tipOf(const Primitive& segment) {
    return segment.frame.position + segment.length * axisOf(segment.frame, {0, 1, 0});
}

// Foliage segments of a chain as ribbons: one quad per segment at LOD0, one
// straight quad per run of kRibbonRun segments at LOD1, `widen` times as wide.
void bakeFoliageChain(DrawnMesh& out, const PlantAsset& asset, const SegmentChain& chain, const LodRecipe& recipe,
                      float widen) {
    const size_t run = recipe.reduced ? kRibbonRun : 1;
    const float minWidth = recipe.scale.minRibbonWidth;
    for (size_t start = 0; start < chain.primitives.size(); start += run) {
        const size_t end = std::min(start + run, chain.primitives.size()) - 1;
        const Primitive& first = asset.primitives[chain.primitives[start]];
        const Primitive& last = asset.primitives[chain.primitives[end]];
        bakeRibbon(out, first.frame, first.frame.position, tipOf(last),
                   widen * std::max(2.0f * first.startRadius, minWidth),
                   widen * std::max(2.0f * last.endRadius, minWidth), first.material, jointOf(first.joint),
                   jointOf(last.joint));
    }
}

void bakePolygon(DrawnMesh& out, const PlantAsset& asset, const Primitive& polygon) {
    const TriangleMesh mesh = polygonMesh(asset.polygons.at(polygon.shape).outline);
    appendTriangleMesh(out, mesh, polygon.material, SurfaceKind::Blade,
                       std::vector<uint32_t>(mesh.vertexCount(), jointOf(polygon.joint)));
}

// Keep one in this many of `count` foliage elements at LOD1 (1 at LOD0).
uint32_t thinningStride(const LodRecipe& recipe, uint32_t count, uint32_t stride) {
    return recipe.reduced ? std::clamp(count / kMinThinned, 1u, stride) : 1u;
}

// Segments with nothing to draw are left out of the chains, as the turtle export does.
std::vector<SegmentChain> drawableChains(const PlantAsset& asset) {
    std::vector<SegmentChain> chains;
    for (SegmentChain& chain : segmentChains(asset)) {
        SegmentChain drawable;
        for (uint32_t p : chain.primitives)
            if (isDrawable(asset.primitives[p])) drawable.primitives.push_back(p);
        if (!drawable.primitives.empty()) chains.push_back(std::move(drawable));
    }
    return chains;
}

DrawnClasses bakeLod(const PlantAsset& asset, const std::vector<SegmentChain>& chains,
                     const std::vector<SurfaceExtent>& extents, const LodRecipe& recipe) {
    DrawnClasses meshes;
    DrawnMesh& bark = meshes[size_t(DrawClass::Bark)];
    DrawnMesh& foliage = meshes[size_t(DrawClass::Foliage)];
    const auto isFoliageChain = [&](const SegmentChain& chain) {
        return isFoliageSegment(asset, asset.primitives[chain.primitives.front()]);
    };
    const auto isLeafCard = [](const Primitive& p) { return isDrawable(p) && p.kind == PrimitiveKind::Surface; };
    const uint32_t ribbonStride =
        thinningStride(recipe, uint32_t(std::count_if(chains.begin(), chains.end(), isFoliageChain)), kRibbonStride);
    const uint32_t leafStride = thinningStride(
        recipe, uint32_t(std::count_if(asset.primitives.begin(), asset.primitives.end(), isLeafCard)), kLeafStride);
    uint32_t foliageChains = 0;
    for (const SegmentChain& chain : chains) {
        if (isFoliageChain(chain)) {
            if (foliageChains++ % ribbonStride == 0)
                bakeFoliageChain(foliage, asset, chain, recipe, float(ribbonStride));
        } else {
            bakeBarkChain(bark, asset, keptPart(asset, chain, recipe), recipe);
        }
    }
    uint32_t leaves = 0;
    for (const Primitive& primitive : asset.primitives) {
        if (!isDrawable(primitive)) continue;
        switch (primitive.kind) {
        case PrimitiveKind::Segment: break; // in the chains
        case PrimitiveKind::Sphere: bakeSphere(bark, asset, primitive, recipe); break;
        case PrimitiveKind::Surface:
            if (leaves++ % leafStride == 0)
                bakeLeafCard(foliage, primitive, extents.at(primitive.shape), std::sqrt(float(leafStride)),
                             recipe.options.leaves);
            break;
        case PrimitiveKind::Polygon: bakePolygon(foliage, asset, primitive); break;
        }
    }
    return meshes;
}

std::vector<SurfaceExtent> surfaceExtents(const PlantAsset& asset) {
    std::vector<SurfaceExtent> extents;
    for (const SurfaceMesh& surface : asset.surfaces) extents.push_back(extentOf(surface));
    return extents;
}

LeafOutline buildLeafOutline() {
    LeafOutline outline;
    outline.uvs.push_back({0.5f, 0.0f});
    for (uint32_t row = 1; row < kLeafOutlineRows; ++row) {
        const double v = double(row) / kLeafOutlineRows;
        const float halfWidth = float(leaf_outline::halfWidth(v));
        outline.uvs.push_back({0.5f - halfWidth, float(v)});
        outline.uvs.push_back({0.5f + halfWidth, float(v)});
    }
    outline.uvs.push_back({0.5f, 1.0f});
    // Row r (1-based) has its left point at 2r − 1 and its right at 2r.
    const uint32_t tip = uint32_t(outline.uvs.size() - 1);
    outline.indices.insert(outline.indices.end(), {0, 2, 1});
    for (uint32_t row = 1; row + 1 < kLeafOutlineRows; ++row) {
        const uint32_t left = 2 * row - 1, right = 2 * row;
        outline.indices.insert(outline.indices.end(), {left, right, right + 2, left, right + 2, left + 2});
    }
    outline.indices.insert(outline.indices.end(), {tip - 2, tip - 1, tip});
    return outline;
}

} // namespace

DrawnScale drawnScaleOf(const PlantAsset& asset) {
    return {trunkRadiusOf(asset), kMinRibbonWidth * largestExtent(asset.bounds)};
}

DrawnScale drawnScaleOf(const std::vector<PlantAsset>& parts, const Bounds& bounds) {
    DrawnScale scale{0.0f, kMinRibbonWidth * largestExtent(bounds)};
    for (const PlantAsset& part : parts) scale.trunkRadius = std::max(scale.trunkRadius, trunkRadiusOf(part));
    return scale;
}

DrawnClasses drawnLod(const PlantAsset& asset, DrawnLod lod, const DrawnScale& scale, const DrawnOptions& options) {
    return bakeLod(asset, drawableChains(asset), surfaceExtents(asset), {lod == DrawnLod::Reduced, scale, options});
}

std::array<DrawnClasses, kDrawnLodCount> drawnLods(const PlantAsset& asset, const DrawnOptions& options) {
    const std::vector<SegmentChain> chains = drawableChains(asset);
    const std::vector<SurfaceExtent> extents = surfaceExtents(asset);
    const DrawnScale scale = drawnScaleOf(asset);
    return {bakeLod(asset, chains, extents, {false, scale, options}),
            bakeLod(asset, chains, extents, {true, scale, options})};
}

std::vector<TriangleMesh> drawnMeshesByMaterial(const PlantAsset& asset, const DrawnScale& scale,
                                                const DrawnOptions& options) {
    std::vector<TriangleMesh> meshes(asset.materials.size());
    for (const DrawnMesh& drawn : drawnLod(asset, DrawnLod::Full, scale, options)) {
        // Every vertex belongs to its material's mesh: its index there.
        std::vector<uint32_t> index(drawn.vertices.size());
        for (size_t i = 0; i < drawn.vertices.size(); ++i) {
            const DrawnVertex& v = drawn.vertices[i];
            TriangleMesh& mesh = meshes.at(v.material);
            index[i] = mesh.vertexCount();
            mesh.positions.push_back(v.position);
            mesh.normals.push_back(v.normal);
            mesh.uvs.push_back(v.uv);
        }
        for (size_t t = 0; t < drawn.indices.size(); ++t) {
            const uint32_t corner = drawn.indices[t];
            meshes[drawn.vertices[corner].material].indices.push_back(index[corner]);
        }
    }
    return meshes;
}

const LeafOutline& leafOutline() {
    static const LeafOutline outline = buildLeafOutline();
    return outline;
}

MeshSize leafOutlineSize() { return {leafOutline().uvs.size(), leafOutline().indices.size()}; }

void appendLeafOutline(TriangleMesh& mesh, glm::vec3 origin, glm::vec3 across, glm::vec3 along, glm::vec3 normal) {
    const LeafOutline& outline = leafOutline();
    const uint32_t base = mesh.vertexCount();
    for (const glm::vec2& uv : outline.uvs) {
        mesh.positions.push_back(onCard(origin, across, along, uv));
        mesh.normals.push_back(normal);
        mesh.uvs.push_back(uv);
    }
    for (uint32_t index : outline.indices) mesh.indices.push_back(base + index);
}

} // namespace lsys
