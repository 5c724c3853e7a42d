// Species meshes of the field: L-system or model file → PlantAsset → two LODs of triangles
// per draw class (docs/FIELD.md "Plant models (meshes and LODs)").
#include "engine/scene/plant_models.h"

#include "engine/scene/joint_params.h"

#include "lsystem/common/error.h"
#include "lsystem/components/component_graph.h"
#include "lsystem/language/parser.h"
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <variant>

namespace pf {
namespace {

// A derivation longer than this is not a plant the field can draw a million
// times; it fails with a message rather than exhausting memory.
constexpr size_t kModuleBudget = 5'000'000;

// The bake (lsystem/mesh/drawn_mesh.h) numbers its kinds, classes and LODs as the
// shaders do.
static_assert(float(lsys::SurfaceKind::Bark) == SURFACE_BARK && float(lsys::SurfaceKind::LeafCard) == SURFACE_LEAF &&
              float(lsys::SurfaceKind::Blade) == SURFACE_BLADE);
static_assert(uint32_t(lsys::DrawClass::Bark) == DRAW_BARK && uint32_t(lsys::DrawClass::Foliage) == DRAW_FOLIAGE &&
              lsys::kDrawClassCount == kMeshClassCount);
static_assert(uint32_t(lsys::DrawnLod::Full) == LOD_FULL && uint32_t(lsys::DrawnLod::Reduced) == LOD_REDUCED &&
              lsys::kDrawnLodCount == kMeshLodCount);

using DrawnLods = std::array<lsys::DrawnClasses, kMeshLodCount>;

// The top of the full-detail mesh: what the species height is measured to.
float topOf(const lsys::DrawnClasses& meshes) {
    float top = std::numeric_limits<float>::lowest();
    for (const lsys::DrawnMesh& mesh : meshes)
        for (const lsys::DrawnVertex& v : mesh.vertices) top = std::max(top, v.position.y);
    return top;
}

// Uniform scale about the base (the origin) so the top reaches `height`; a
// plant with no height above its base keeps its own units. Returns the
// scale, which the skeleton gets too.
float scaleToHeight(DrawnLods& lods, float height) {
    const float top = topOf(lods[LOD_FULL]);
    if (!(top > 0.0f)) return 1.0f;
    const float scale = height / top;
    for (lsys::DrawnClasses& lod : lods)
        for (lsys::DrawnMesh& mesh : lod)
            for (lsys::DrawnVertex& v : mesh.vertices) v.position *= scale;
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

// What a species' variants are made from, read once: an L-system's grammar,
// a ramification tree type (Tankard 2001, §3.3) or a component graph (§3.2).
using PlantSource = std::variant<lsys::Grammar, lsys::RamificationTree, lsys::components::ComponentGraph>;

const std::filesystem::path& plantFile(const Species& species) {
    return species.lsystem.empty() ? species.model : species.lsystem;
}

PlantSource readPlantSource(const Species& species, std::string& warnings) {
    if (!species.lsystem.empty()) return parseSpecies(species, warnings);
    const std::string which = "species '" + species.name + "': ";
    if (lsys::isRamificationFile(species.model)) {
        lsys::RamificationFile file = lsys::readRamificationFile(species.model);
        if (!file.tree) throw SceneError(which + lsys::formatDiagnostics(file.diagnostics, file.source));
        return std::move(*file.tree);
    }
    try {
        return lsys::components::readComponentGraph(species.model);
    } catch (const lsys::components::ComponentError& error) { // located in the file already
        throw SceneError(which + error.what());
    }
}

// The plant of one variant: the source made with `seed` in place of the
// file's own, as L-system variants derive with theirs.
lsys::PlantAsset plantOfVariant(const PlantSource& source, const lsys::SurfaceLibrary& surfaces,
                                const std::optional<uint32_t>& steps, uint64_t seed, const lsys::MemoryBudget& memory) {
    if (const auto* grammar = std::get_if<lsys::Grammar>(&source)) {
        lsys::DeriveOptions options;
        if (steps) options.steps = int(*steps);
        options.seed = seed;
        options.maxModules = kModuleBudget;
        options.memory = memory;
        return lsys::plantFromGrammar(*grammar, lsys::derive(*grammar, options), surfaces, memory);
    }
    if (const auto* tree = std::get_if<lsys::RamificationTree>(&source)) {
        lsys::RamificationTree seeded = *tree;
        seeded.seed = seed;
        return lsys::plantOf(lsys::generateTree(seeded), memory);
    }
    lsys::components::ComponentGraph seeded = std::get<lsys::components::ComponentGraph>(source);
    seeded.seed = seed;
    return lsys::components::buildComponentPlant(seeded, memory);
}

lsys::PlantAsset speciesPlant(const Species& species, const PlantSource& source, const lsys::SurfaceLibrary& surfaces,
                              uint64_t seed, const lsys::MemoryBudget& memory) {
    const std::string which =
        "species '" + species.name + "' (" + plantFile(species).string() + ", seed " + std::to_string(seed) + "): ";
    try {
        return plantOfVariant(source, surfaces, species.steps, seed, memory);
    } catch (const lsys::MemoryBudgetError& error) { // the species too large for the budget: its type kept
        throw lsys::MemoryBudgetError(which + error.what());
    } catch (const lsys::ModuleBudgetError& error) {
        throw lsys::ModuleBudgetError(which + error.what() + "; give the species fewer \"steps\"");
    } catch (const std::runtime_error& error) { // DerivationError, SurfaceError, ComponentError: the species' own fault
        throw SceneError(which + error.what());
    }
}

void applyMaterialOverrides(lsys::PlantAsset& asset, const std::vector<MaterialOverride>& overrides) {
    for (const MaterialOverride& material : overrides)
        if (material.index < asset.materials.size()) asset.materials[material.index].albedo = material.albedo;
}

gpu::FieldVertex packed(const lsys::DrawnVertex& v, const std::vector<lsys::Material>& materials) {
    return {glm::vec4(v.position, v.uv.x), glm::vec4(v.normal, v.uv.y),
            glm::vec4(materials[v.material].albedo, float(v.kind)), glm::uvec4(v.joint, 0, 0, 0)};
}

MeshRange appendToPool(PlantModelPool& pool, const lsys::DrawnMesh& mesh,
                       const std::vector<lsys::Material>& materials) {
    const MeshRange range{uint32_t(pool.indices.size()), uint32_t(mesh.indices.size()), uint32_t(pool.vertices.size())};
    for (const lsys::DrawnVertex& v : mesh.vertices) pool.vertices.push_back(packed(v, materials));
    pool.indices.insert(pool.indices.end(), mesh.indices.begin(), mesh.indices.end());
    return range;
}

// Box and sphere around every vertex of both LODs (LOD1's enlarged leaves
// may reach past LOD0's), so culling never clips either.
void fillBounds(gpu::PlantModel& model, const DrawnLods& lods) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const lsys::DrawnClasses& lod : lods)
        for (const lsys::DrawnMesh& mesh : lod)
            for (const lsys::DrawnVertex& v : mesh.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
            }
    if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (const lsys::DrawnClasses& lod : lods)
        for (const lsys::DrawnMesh& mesh : lod)
            for (const lsys::DrawnVertex& v : mesh.vertices)
                radius = std::max(radius, glm::distance(centre, v.position));
    model.sphere = glm::vec4(centre, radius);
    model.boxMin = glm::vec4(lo, 0.0f);
    model.boxMax = glm::vec4(hi, 0.0f);
}

// What the pool holds so far: each model is built within what is left of
// the budget after it, and the pool itself is counted, so that many models
// each within the budget cannot together pass it.
uint64_t poolBytes(const PlantModelPool& pool) {
    uint64_t bytes = lsys::bytesPlus(lsys::bytesTimes(pool.vertices.capacity(), sizeof(gpu::FieldVertex)),
                                     lsys::bytesTimes(pool.indices.capacity(), sizeof(uint32_t)));
    bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(pool.joints.capacity(), sizeof(gpu::JointParams)));
    bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(pool.models.capacity(), sizeof(PlantModelInfo)));
    for (const PlantModelAsset& kept : pool.assets) {
        const lsys::PlantAsset& asset = kept.asset;
        bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(asset.primitives.size(), sizeof(lsys::Primitive)));
        bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(asset.joints.size(), sizeof(lsys::Joint)));
        for (const lsys::SurfaceMesh& surface : asset.surfaces) {
            const uint64_t perVertex = sizeof(glm::vec3) * 2 + sizeof(glm::vec2); // position, normal, uv
            bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(surface.positions.size(), perVertex));
            bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(surface.indices.size(), sizeof(uint32_t)));
        }
    }
    return bytes;
}

// Grows the pool's vertex and index arrays to take `vertices` and `indices`
// more, refusing first when the arrays, old and new alive at once while they
// move, would pass the budget (a vector doubling would otherwise jump past it).
void reservePool(PlantModelPool& pool, size_t vertices, size_t indices, const lsys::MemoryBudget& memory,
                 const std::string& model) {
    const auto grown = [](size_t capacity, size_t needed) {
        return needed <= capacity ? capacity : std::max(needed, capacity + capacity / 2);
    };
    const size_t vertexCapacity = grown(pool.vertices.capacity(), pool.vertices.size() + vertices);
    const size_t indexCapacity = grown(pool.indices.capacity(), pool.indices.size() + indices);
    uint64_t moving = 0;
    if (vertexCapacity != pool.vertices.capacity())
        moving = lsys::bytesPlus(moving, lsys::bytesTimes(vertexCapacity, sizeof(gpu::FieldVertex)));
    if (indexCapacity != pool.indices.capacity())
        moving = lsys::bytesPlus(moving, lsys::bytesTimes(indexCapacity, sizeof(uint32_t)));
    lsys::need(memory, "plant models (" + model + " and the " + std::to_string(pool.models.size()) + " before it)",
               lsys::bytesPlus(poolBytes(pool), moving));
    pool.vertices.reserve(vertexCapacity);
    pool.indices.reserve(indexCapacity);
}

PlantModelInfo buildModel(PlantModelPool& pool, const Scene& scene, uint32_t speciesIndex, uint32_t variant,
                          const PlantSource& source, const lsys::SurfaceLibrary& surfaces,
                          const lsys::MemoryBudget& memory, ModelAssets assets) {
    const Species& species = scene.species[speciesIndex];
    const uint64_t seed = uint64_t(speciesSeed(scene, speciesIndex)) + variant;
    const uint64_t held = poolBytes(pool); // the plant is made within what the pool leaves
    lsys::PlantAsset asset = speciesPlant(species, source, surfaces, seed,
                                          lsys::MemoryBudget{memory.limitBytes > held ? memory.limitBytes - held : 0});
    applyMaterialOverrides(asset, species.materials);
    DrawnLods lods = lsys::drawnLods(asset);
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
    size_t vertices = 0, indices = 0;
    for (const lsys::DrawnClasses& meshes : lods)
        for (const lsys::DrawnMesh& mesh : meshes) {
            vertices += mesh.vertices.size();
            indices += mesh.indices.size();
        }
    reservePool(pool, vertices, indices, memory, info.name);
    for (uint32_t lod = 0; lod < kMeshLodCount; ++lod)
        for (uint32_t drawClass = 0; drawClass < kMeshClassCount; ++drawClass)
            info.meshes[lod][drawClass] = appendToPool(pool, lods[lod][drawClass], asset.materials);
    fillBounds(info.gpu, lods);
    info.gpu.lod = glm::vec4(species.lod.reducedBelowPixels, species.lod.impostorBelowPixels, 0.1f, 0.25f);
    info.gpu.boxMax.w = species.lod.hiddenBelowPixels;
    if (assets == ModelAssets::Keep) pool.assets.push_back({std::move(asset), scale});
    return info;
}

} // namespace

PlantModelPool buildPlantModels(const Scene& scene, const ModelProgress& progress, const lsys::MemoryBudget& memory,
                                ModelAssets assets) {
    size_t total = 0;
    for (const Species& species : scene.species) total += species.variants;
    PlantModelPool pool;
    for (uint32_t s = 0; s < scene.species.size(); ++s) {
        const PlantSource source = readPlantSource(scene.species[s], pool.warnings);
        const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(plantFile(scene.species[s])));
        pool.firstModel.push_back(uint32_t(pool.models.size()));
        for (uint32_t variant = 0; variant < scene.species[s].variants; ++variant) {
            pool.models.push_back(buildModel(pool, scene, s, variant, source, surfaces, memory, assets));
            lsys::need(memory,
                       "plant models (" + pool.models.back().name + " and the " +
                           std::to_string(pool.models.size() - 1) + " before it)",
                       poolBytes(pool));
            if (progress) progress(pool.models.size(), total, pool.models.back().name);
        }
    }
    return pool;
}

} // namespace pf
