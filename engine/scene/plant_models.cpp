// Species meshes of the field: L-system → PlantAsset → two LODs of triangles
// per draw class (docs/FIELD.md "Plant models (meshes and LODs)").
#include "engine/scene/plant_models.h"

#include "engine/scene/joint_params.h"

#include "lsystem/error.h"
#include "lsystem/parser.h"
#include "lsystem/primitive_mesh.h"
#include "lsystem/rewriter.h"
#include "lsystem/surfaces.h"
#include "lsystem/turtle.h"
#include "lsystem/vlab/object.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pf {
namespace {

// A derivation longer than this is not a plant the field can draw a million
// times; it fails with a message rather than exhausting memory.
constexpr size_t kModuleBudget = 5'000'000;

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

// What one vertex carries before it is packed into a FieldVertex.
struct BakeVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec3 albedo;
    float kind;
    uint32_t joint;
};

struct BakedMesh {
    std::vector<BakeVertex> vertices;
    std::vector<uint32_t> indices;
};

using ClassMeshes = std::array<BakedMesh, kMeshClassCount>;

// Primitive::joint of the plant's base (-1) moves with the first joint: at
// the base it barely moves, and the skeleton needs no extra root entry.
uint32_t jointOf(int32_t joint) { return joint < 0 ? 0u : uint32_t(joint); }

void appendTriangleMesh(BakedMesh& out, const lsys::TriangleMesh& mesh, glm::vec3 albedo, float kind,
                        const std::vector<uint32_t>& joints) {
    const uint32_t base = uint32_t(out.vertices.size());
    for (uint32_t i = 0; i < mesh.vertexCount(); ++i)
        out.vertices.push_back({mesh.positions[i], mesh.normals[i], mesh.uvs[i], albedo, kind, joints[i]});
    for (uint32_t index : mesh.indices) out.indices.push_back(base + index);
}

// A quad a b c d (counter-clockwise seen from `normal`), two triangles.
void appendQuad(BakedMesh& out, const std::array<BakeVertex, 4>& corners) {
    const uint32_t base = uint32_t(out.vertices.size());
    out.vertices.insert(out.vertices.end(), corners.begin(), corners.end());
    out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

glm::vec3 axisOf(const lsys::Frame& frame, glm::vec3 local) { return frame.rotation * local; }

bool isFoliageSegment(const lsys::PlantAsset& asset, const lsys::Primitive& primitive) {
    return primitive.kind == lsys::PrimitiveKind::Segment && asset.materials.at(primitive.material).twoSided;
}

float trunkRadius(const lsys::PlantAsset& asset) {
    float radius = 0.0f;
    for (const lsys::Primitive& p : asset.primitives)
        if (p.kind == lsys::PrimitiveKind::Segment && !isFoliageSegment(asset, p))
            radius = std::max({radius, p.startRadius, p.endRadius});
    return radius;
}

float largestExtent(const lsys::PlantAsset& asset) {
    if (asset.bounds.empty()) return 1.0f;
    const glm::vec3 size = asset.bounds.max - asset.bounds.min;
    return std::max({size.x, size.y, size.z, 1e-3f});
}

// Everything that decides how one LOD is baked.
struct LodRecipe {
    bool reduced = false;
    float trunkRadius = 0.0f;
    float minRibbonWidth = 0.0f;
};

// Ring sides of a bark tube from its thickness relative to the trunk: the
// trunk is round up close, twigs need only a few sides.
uint32_t barkSides(const LodRecipe& recipe, float radius) {
    const float relative = recipe.trunkRadius > 0.0f ? radius / recipe.trunkRadius : 1.0f;
    if (recipe.reduced) return relative >= 0.25f ? 4u : 3u;
    if (relative >= 0.25f) return 8u;
    if (relative >= 0.06f) return 6u;
    return relative >= 0.02f ? 4u : 3u;
}

// The chain without its segments thinner than the LOD keeps (radii shrink
// toward the tip, so that is a tip part).
lsys::SegmentChain keptPart(const lsys::PlantAsset& asset, const lsys::SegmentChain& chain, const LodRecipe& recipe) {
    if (!recipe.reduced) return chain;
    lsys::SegmentChain kept;
    for (uint32_t p : chain.primitives) {
        const lsys::Primitive& segment = asset.primitives[p];
        if (std::max(segment.startRadius, segment.endRadius) < kTwigFraction * recipe.trunkRadius) break;
        kept.primitives.push_back(p);
    }
    return kept;
}

// One generalised cylinder per chain of bark segments; each ring moves with
// the segment whose tip it is (the base ring with the first segment).
void bakeBarkChain(BakedMesh& out, const lsys::PlantAsset& asset, const lsys::SegmentChain& chain,
                   const LodRecipe& recipe) {
    if (chain.primitives.empty()) return;
    const lsys::Primitive& first = asset.primitives[chain.primitives.front()];
    lsys::MeshDetail detail;
    detail.segmentSides = barkSides(recipe, first.startRadius);
    detail.segmentCaps = !recipe.reduced;
    const lsys::TriangleMesh mesh = lsys::generalizedCylinderMesh(asset, chain, detail);
    const uint32_t ringVertices = detail.segmentSides + 1;
    const size_t rings = chain.primitives.size() + 1;
    std::vector<uint32_t> joints(mesh.vertexCount());
    for (uint32_t i = 0; i < mesh.vertexCount(); ++i) {
        const size_t ring = i / ringVertices;
        // Ring r is the tip of segment r-1; cap vertices follow the rings: base cap, then tip cap.
        const size_t segment = ring < rings ? (ring == 0 ? 0 : ring - 1) : (ring == rings ? 0 : rings - 2);
        joints[i] = jointOf(asset.primitives[chain.primitives[segment]].joint);
    }
    appendTriangleMesh(out, mesh, asset.materials[first.material].albedo, SURFACE_BARK, joints);
}

void bakeSphere(BakedMesh& out, const lsys::PlantAsset& asset, const lsys::Primitive& sphere, const LodRecipe& recipe) {
    lsys::MeshDetail detail;
    detail.sphereSlices = recipe.reduced ? 4 : 8;
    detail.sphereStacks = recipe.reduced ? 3 : 6;
    const lsys::TriangleMesh mesh = lsys::bakedPrimitiveMesh(asset, sphere, detail);
    appendTriangleMesh(out, mesh, asset.materials[sphere.material].albedo, SURFACE_BARK,
                       std::vector<uint32_t>(mesh.vertexCount(), jointOf(sphere.joint)));
}

// Local x and y extent of a surface: the card spans it.
struct SurfaceExtent {
    glm::vec2 min{0.0f}, max{0.0f};
};

SurfaceExtent extentOf(const lsys::SurfaceMesh& surface) {
    SurfaceExtent extent{glm::vec2(std::numeric_limits<float>::max()), glm::vec2(std::numeric_limits<float>::lowest())};
    for (const glm::vec3& p : surface.positions) {
        extent.min = glm::min(extent.min, glm::vec2(p));
        extent.max = glm::max(extent.max, glm::vec2(p));
    }
    if (surface.positions.empty()) extent = {};
    return extent;
}

// A leaf card: the surface's x-y extent on the surface's plane, petiole
// (v = 0) at its local -y end. `enlarge` grows it about the petiole's midpoint.
void bakeLeafCard(BakedMesh& out, const lsys::PlantAsset& asset, const lsys::Primitive& surface,
                  const SurfaceExtent& extent, float enlarge) {
    const float scale = surface.length;
    const glm::vec3 x = axisOf(surface.frame, {1, 0, 0}), y = axisOf(surface.frame, {0, 1, 0});
    const glm::vec3 normal = axisOf(surface.frame, {0, 0, 1});
    const glm::vec3 origin =
        surface.frame.position + scale * (x * 0.5f * (extent.min.x + extent.max.x) + y * extent.min.y);
    const glm::vec3 across = scale * enlarge * x * (extent.max.x - extent.min.x);
    const glm::vec3 along = scale * enlarge * y * (extent.max.y - extent.min.y);
    const glm::vec3 albedo = asset.materials[surface.material].albedo;
    const uint32_t joint = jointOf(surface.joint);
    const auto corner = [&](float u, float v) {
        return BakeVertex{origin + (u - 0.5f) * across + v * along, normal, {u, v}, albedo, SURFACE_LEAF, joint};
    };
    appendQuad(out, {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)});
}

// A flat ribbon from `base` to `tip` across the frame's local x, facing its
// local z; u across, v along.
void bakeRibbon(BakedMesh& out, const lsys::Frame& frame, glm::vec3 base, glm::vec3 tip, float baseWidth,
                float tipWidth, glm::vec3 albedo, uint32_t baseJoint, uint32_t tipJoint) {
    const glm::vec3 across = axisOf(frame, {1, 0, 0}), normal = axisOf(frame, {0, 0, 1});
    appendQuad(out, {BakeVertex{base - 0.5f * baseWidth * across, normal, {0, 0}, albedo, SURFACE_BLADE, baseJoint},
                     BakeVertex{base + 0.5f * baseWidth * across, normal, {1, 0}, albedo, SURFACE_BLADE, baseJoint},
                     BakeVertex{tip + 0.5f * tipWidth * across, normal, {1, 1}, albedo, SURFACE_BLADE, tipJoint},
                     BakeVertex{tip - 0.5f * tipWidth * across, normal, {0, 1}, albedo, SURFACE_BLADE, tipJoint}});
}

glm::vec3 tipOf(const lsys::Primitive& segment) {
    return segment.frame.position + segment.length * axisOf(segment.frame, {0, 1, 0});
}

// Foliage segments of a chain as ribbons: one quad per segment at LOD0, one
// straight quad per run of kRibbonRun segments at LOD1, `widen` times as wide.
void bakeFoliageChain(BakedMesh& out, const lsys::PlantAsset& asset, const lsys::SegmentChain& chain,
                      const LodRecipe& recipe, float widen) {
    const size_t run = recipe.reduced ? kRibbonRun : 1;
    for (size_t start = 0; start < chain.primitives.size(); start += run) {
        const size_t end = std::min(start + run, chain.primitives.size()) - 1;
        const lsys::Primitive& first = asset.primitives[chain.primitives[start]];
        const lsys::Primitive& last = asset.primitives[chain.primitives[end]];
        bakeRibbon(out, first.frame, first.frame.position, tipOf(last),
                   widen * std::max(2.0f * first.startRadius, recipe.minRibbonWidth),
                   widen * std::max(2.0f * last.endRadius, recipe.minRibbonWidth),
                   asset.materials[first.material].albedo, jointOf(first.joint), jointOf(last.joint));
    }
}

void bakePolygon(BakedMesh& out, const lsys::PlantAsset& asset, const lsys::Primitive& polygon) {
    const lsys::TriangleMesh mesh = lsys::polygonMesh(asset.polygons.at(polygon.shape).outline);
    appendTriangleMesh(out, mesh, asset.materials[polygon.material].albedo, SURFACE_BLADE,
                       std::vector<uint32_t>(mesh.vertexCount(), jointOf(polygon.joint)));
}

// Keep one in this many of `count` foliage elements at LOD1 (1 at LOD0).
uint32_t thinningStride(const LodRecipe& recipe, uint32_t count, uint32_t stride) {
    return recipe.reduced ? std::clamp(count / kMinThinned, 1u, stride) : 1u;
}

ClassMeshes bakeLod(const lsys::PlantAsset& asset, const std::vector<lsys::SegmentChain>& chains,
                    const std::vector<SurfaceExtent>& extents, const LodRecipe& recipe) {
    ClassMeshes meshes;
    BakedMesh& bark = meshes[DRAW_BARK];
    BakedMesh& foliage = meshes[DRAW_FOLIAGE];
    const auto isFoliageChain = [&](const lsys::SegmentChain& chain) {
        return isFoliageSegment(asset, asset.primitives[chain.primitives.front()]);
    };
    const auto isLeafCard = [](const lsys::Primitive& p) {
        return lsys::isDrawable(p) && p.kind == lsys::PrimitiveKind::Surface;
    };
    const uint32_t ribbonStride =
        thinningStride(recipe, uint32_t(std::count_if(chains.begin(), chains.end(), isFoliageChain)), kRibbonStride);
    const uint32_t leafStride = thinningStride(
        recipe, uint32_t(std::count_if(asset.primitives.begin(), asset.primitives.end(), isLeafCard)), kLeafStride);
    uint32_t foliageChains = 0;
    for (const lsys::SegmentChain& chain : chains) {
        if (isFoliageChain(chain)) {
            if (foliageChains++ % ribbonStride == 0)
                bakeFoliageChain(foliage, asset, chain, recipe, float(ribbonStride));
        } else {
            bakeBarkChain(bark, asset, keptPart(asset, chain, recipe), recipe);
        }
    }
    uint32_t leaves = 0;
    for (const lsys::Primitive& primitive : asset.primitives) {
        if (!lsys::isDrawable(primitive)) continue;
        switch (primitive.kind) {
        case lsys::PrimitiveKind::Segment: break; // in the chains
        case lsys::PrimitiveKind::Sphere: bakeSphere(bark, asset, primitive, recipe); break;
        case lsys::PrimitiveKind::Surface:
            if (leaves++ % leafStride == 0)
                bakeLeafCard(foliage, asset, primitive, extents.at(primitive.shape), std::sqrt(float(leafStride)));
            break;
        case lsys::PrimitiveKind::Polygon: bakePolygon(foliage, asset, primitive); break;
        }
    }
    return meshes;
}

// Segments with nothing to draw are left out of the chains, as the exporter does.
std::vector<lsys::SegmentChain> drawableChains(const lsys::PlantAsset& asset) {
    std::vector<lsys::SegmentChain> chains;
    for (lsys::SegmentChain& chain : lsys::segmentChains(asset)) {
        lsys::SegmentChain drawable;
        for (uint32_t p : chain.primitives)
            if (lsys::isDrawable(asset.primitives[p])) drawable.primitives.push_back(p);
        if (!drawable.primitives.empty()) chains.push_back(std::move(drawable));
    }
    return chains;
}

std::array<ClassMeshes, kMeshLodCount> bakeLods(const lsys::PlantAsset& asset) {
    const std::vector<lsys::SegmentChain> chains = drawableChains(asset);
    std::vector<SurfaceExtent> extents;
    for (const lsys::SurfaceMesh& surface : asset.surfaces) extents.push_back(extentOf(surface));
    LodRecipe recipe{false, trunkRadius(asset), kMinRibbonWidth * largestExtent(asset)};
    std::array<ClassMeshes, kMeshLodCount> lods;
    lods[LOD_FULL] = bakeLod(asset, chains, extents, recipe);
    recipe.reduced = true;
    lods[LOD_REDUCED] = bakeLod(asset, chains, extents, recipe);
    return lods;
}

// The top of the full-detail mesh: what the species height is measured to.
float topOf(const ClassMeshes& meshes) {
    float top = std::numeric_limits<float>::lowest();
    for (const BakedMesh& mesh : meshes)
        for (const BakeVertex& v : mesh.vertices) top = std::max(top, v.position.y);
    return top;
}

// Uniform scale about the base (the origin) so the top reaches `height`; a
// plant with no height above its base keeps its own units. Returns the
// scale, which the skeleton gets too.
float scaleToHeight(std::array<ClassMeshes, kMeshLodCount>& lods, float height) {
    const float top = topOf(lods[LOD_FULL]);
    if (!(top > 0.0f)) return 1.0f;
    const float scale = height / top;
    for (ClassMeshes& lod : lods)
        for (BakedMesh& mesh : lod)
            for (BakeVertex& v : mesh.vertices) v.position *= scale;
    return scale;
}

// The species' grammar; its warnings are appended to `warnings`.
lsys::Grammar parseSpecies(const Species& species, std::string& warnings) {
    lsys::ParseOptions options;
    options.defines.insert(species.defines.begin(), species.defines.end());
    lsys::vlab::PlantFile plant = lsys::vlab::loadPlant(species.lsystem, std::nullopt, options);
    const std::string which = "species '" + species.name + "': ";
    if (!plant.parsed.ok()) throw SceneError(which + lsys::formatDiagnostics(plant.parsed.diagnostics, plant.source));
    if (!plant.parsed.warnings.empty())
        warnings += which + lsys::formatDiagnostics(plant.parsed.warnings, plant.source);
    return std::move(plant.parsed.grammar);
}

lsys::PlantAsset derivePlant(const Species& species, const lsys::Grammar& grammar, const lsys::SurfaceLibrary& surfaces,
                             uint64_t seed, const lsys::MemoryBudget& memory) {
    lsys::DeriveOptions options;
    if (species.steps) options.steps = int(*species.steps);
    options.seed = seed;
    options.maxModules = kModuleBudget;
    options.memory = memory;
    const std::string which =
        "species '" + species.name + "' (" + species.lsystem.string() + ", seed " + std::to_string(seed) + "): ";
    try {
        const lsys::ModuleString derived = lsys::derive(grammar, options);
        return lsys::plantFromGrammar(grammar, derived, surfaces, memory);
    } catch (const lsys::MemoryBudgetError& error) { // the species too large for the budget: its type kept
        throw lsys::MemoryBudgetError(which + error.what());
    } catch (const lsys::ModuleBudgetError& error) {
        throw lsys::ModuleBudgetError(which + error.what() + "; give the species fewer \"steps\"");
    } catch (const std::runtime_error& error) { // DerivationError, SurfaceError: the species' own fault
        throw SceneError(which + error.what());
    }
}

void applyMaterialOverrides(lsys::PlantAsset& asset, const std::vector<MaterialOverride>& overrides) {
    for (const MaterialOverride& material : overrides)
        if (material.index < asset.materials.size()) asset.materials[material.index].albedo = material.albedo;
}

gpu::FieldVertex packed(const BakeVertex& v) {
    return {glm::vec4(v.position, v.uv.x), glm::vec4(v.normal, v.uv.y), glm::vec4(v.albedo, v.kind),
            glm::uvec4(v.joint, 0, 0, 0)};
}

MeshRange appendToPool(PlantModelPool& pool, const BakedMesh& mesh) {
    const MeshRange range{uint32_t(pool.indices.size()), uint32_t(mesh.indices.size()), uint32_t(pool.vertices.size())};
    for (const BakeVertex& v : mesh.vertices) pool.vertices.push_back(packed(v));
    pool.indices.insert(pool.indices.end(), mesh.indices.begin(), mesh.indices.end());
    return range;
}

// Box and sphere around every vertex of both LODs (LOD1's enlarged leaves
// may reach past LOD0's), so culling never clips either.
void fillBounds(gpu::PlantModel& model, const std::array<ClassMeshes, kMeshLodCount>& lods) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const ClassMeshes& lod : lods)
        for (const BakedMesh& mesh : lod)
            for (const BakeVertex& v : mesh.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
            }
    if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (const ClassMeshes& lod : lods)
        for (const BakedMesh& mesh : lod)
            for (const BakeVertex& v : mesh.vertices) radius = std::max(radius, glm::distance(centre, v.position));
    model.sphere = glm::vec4(centre, radius);
    model.boxMin = glm::vec4(lo, 0.0f);
    model.boxMax = glm::vec4(hi, 0.0f);
}

PlantModelInfo buildModel(PlantModelPool& pool, const Scene& scene, uint32_t speciesIndex, uint32_t variant,
                          const lsys::Grammar& grammar, const lsys::SurfaceLibrary& surfaces,
                          const lsys::MemoryBudget& memory) {
    const Species& species = scene.species[speciesIndex];
    const uint64_t seed = uint64_t(speciesSeed(scene, speciesIndex)) + variant;
    lsys::PlantAsset asset = derivePlant(species, grammar, surfaces, seed, memory);
    applyMaterialOverrides(asset, species.materials);
    std::array<ClassMeshes, kMeshLodCount> lods = bakeLods(asset);
    const float scale = species.height ? scaleToHeight(lods, *species.height) : 1.0f;

    PlantModelInfo info;
    info.species = speciesIndex;
    info.variant = variant;
    info.name = species.name + "#" + std::to_string(variant);
    info.joints = uint32_t(asset.joints.size());
    // Joint j of the asset is params[firstJoint + j]: the vertices' joint.x numbering.
    info.firstJoint = uint32_t(pool.joints.size());
    const std::vector<gpu::JointParams> skeleton = buildJointParams(asset, scale, scene.physics);
    pool.joints.insert(pool.joints.end(), skeleton.begin(), skeleton.end());
    info.billboard = species.lod.billboard;
    for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
        for (uint32_t drawClass = 0; drawClass < kMeshClassCount; ++drawClass)
            info.meshes[lod][drawClass] = appendToPool(pool, lods[lod][drawClass]);
    fillBounds(info.gpu, lods);
    info.gpu.lod = glm::vec4(species.lod.reducedBelowPixels, species.lod.impostorBelowPixels, 0.1f, 0.25f);
    info.gpu.boxMax.w = species.lod.hiddenBelowPixels;
    return info;
}

} // namespace

PlantModelPool buildPlantModels(const Scene& scene, const ModelProgress& progress, const lsys::MemoryBudget& memory) {
    size_t total = 0;
    for (const Species& species : scene.species) total += species.variants;
    PlantModelPool pool;
    for (uint32_t s = 0; s < scene.species.size(); ++s) {
        const lsys::Grammar grammar = parseSpecies(scene.species[s], pool.warnings);
        const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(scene.species[s].lsystem));
        pool.firstModel.push_back(uint32_t(pool.models.size()));
        for (uint32_t variant = 0; variant < scene.species[s].variants; ++variant) {
            pool.models.push_back(buildModel(pool, scene, s, variant, grammar, surfaces, memory));
            if (progress) progress(pool.models.size(), total, pool.models.back().name);
        }
    }
    return pool;
}

} // namespace pf
