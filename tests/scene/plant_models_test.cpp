// Species meshes of the field (engine/scene/plant_models.h): the default scene's
// pool is well formed, LOD1 is lighter, bounds and heights hold, builds are
// deterministic, and broken L-systems fail with their position.
#include "engine/scene/plant_models.h"

#include "lsystem/mesh/drawn_mesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

namespace {

const std::filesystem::path kData = PLANTFIELD_DATA_DIR;
const std::filesystem::path kOutput = PLANTFIELD_TEST_OUTPUT_DIR;

// Built once: every test below reads the same default pool.
const pf::Scene& defaultScene() {
    static const pf::Scene scene = pf::loadScene(kData / "scenes" / "default.json");
    return scene;
}

const pf::PlantModelPool& defaultPool() {
    static const pf::PlantModelPool pool = pf::buildPlantModels(defaultScene());
    return pool;
}

// Species that the default forest draws as trees (checked for LOD1 ≤ 40 %).
bool isTree(const pf::Species& species) { return species.height && *species.height >= 5.0f; }

template <typename F>
void forEachMesh(const pf::PlantModelInfo& model, F f) {
    for (uint32_t lod = 0; lod < pf::kMeshLodCount; ++lod)
        for (uint32_t drawClass = 0; drawClass < pf::kMeshClassCount; ++drawClass)
            f(lod, drawClass, model.meshes[lod][drawClass]);
}

// Vertices a mesh's indices may reach: up to the next mesh's first vertex.
uint32_t verticesOf(const pf::PlantModelPool& pool, const pf::MeshRange& range) {
    uint32_t end = uint32_t(pool.vertices.size());
    for (const pf::PlantModelInfo& model : pool.models)
        forEachMesh(model, [&](uint32_t, uint32_t, const pf::MeshRange& other) {
            if (other.vertexOffset > range.vertexOffset) end = std::min(end, other.vertexOffset);
        });
    return end - range.vertexOffset;
}

std::filesystem::path writePlant(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(kOutput);
    const std::filesystem::path path = kOutput / name;
    std::ofstream(path) << text;
    return path;
}

pf::Scene sceneOf(const std::filesystem::path& lsystem, uint32_t variants) {
    pf::Scene scene;
    pf::Species species;
    species.name = "probe";
    species.lsystem = lsystem;
    species.variants = variants;
    scene.species.push_back(species);
    return scene;
}

TEST(PlantModels, DefaultSceneHasEverySpeciesAndVariant) {
    const pf::Scene& scene = defaultScene();
    const pf::PlantModelPool& pool = defaultPool();
    ASSERT_GE(scene.species.size(), 4u);
    ASSERT_EQ(pool.firstModel.size(), scene.species.size());
    for (uint32_t s = 0; s < scene.species.size(); ++s)
        for (uint32_t v = 0; v < scene.species[s].variants; ++v) {
            const pf::PlantModelInfo& model = pool.models.at(pool.modelOf(s, v));
            EXPECT_EQ(model.species, s);
            EXPECT_EQ(model.variant, v);
            EXPECT_EQ(model.name, scene.species[s].name + "#" + std::to_string(v));
            EXPECT_GT(model.triangles(LOD_FULL), 0u) << model.name;
            EXPECT_GT(model.joints, 0u) << model.name;
            EXPECT_EQ(model.gpu.lod.x, scene.species[s].lod.reducedBelowPixels);
            EXPECT_EQ(model.gpu.lod.y, scene.species[s].lod.impostorBelowPixels);
        }
}

TEST(PlantModels, RangesAndIndicesLieInsideThePool) {
    const pf::PlantModelPool& pool = defaultPool();
    for (const pf::PlantModelInfo& model : pool.models)
        forEachMesh(model, [&](uint32_t lod, uint32_t drawClass, const pf::MeshRange& range) {
            ASSERT_LE(uint64_t(range.firstIndex) + range.indexCount, pool.indices.size()) << model.name;
            ASSERT_EQ(range.indexCount % 3, 0u);
            if (range.indexCount == 0) return;
            const uint32_t vertices = verticesOf(pool, range);
            ASSERT_LE(uint64_t(range.vertexOffset) + vertices, pool.vertices.size());
            for (uint32_t i = 0; i < range.indexCount; ++i)
                ASSERT_LT(pool.indices[range.firstIndex + i], vertices)
                    << model.name << " lod " << lod << " class " << drawClass;
            for (uint32_t i = 0; i < vertices; ++i) {
                const gpu::FieldVertex& v = pool.vertices[range.vertexOffset + i];
                ASSERT_LT(v.joint.x, model.joints) << model.name;
                ASSERT_NEAR(glm::length(glm::vec3(v.normal)), 1.0f, 1e-3f) << model.name;
                const float kind = v.albedo.w;
                if (drawClass == DRAW_BARK)
                    ASSERT_EQ(kind, SURFACE_BARK);
                else
                    ASSERT_TRUE(kind == SURFACE_LEAF || kind == SURFACE_BLADE);
                if (kind == SURFACE_LEAF) {
                    ASSERT_GE(v.position.w, 0.0f);
                    ASSERT_LE(v.position.w, 1.0f);
                    ASSERT_GE(v.normal.w, 0.0f);
                    ASSERT_LE(v.normal.w, 1.0f);
                }
            }
        });
}

TEST(PlantModels, ReducedLodIsLighterAndTreesAreAtMostFortyPercent) {
    const pf::Scene& scene = defaultScene();
    const pf::PlantModelPool& pool = defaultPool();
    for (const pf::PlantModelInfo& model : pool.models) {
        const uint32_t full = model.triangles(LOD_FULL), reduced = model.triangles(LOD_REDUCED);
        std::cout << model.name << ": LOD0 " << full << " triangles, LOD1 " << reduced << '\n';
        EXPECT_GT(reduced, 0u) << model.name;
        EXPECT_LT(reduced, full) << model.name;
        if (isTree(scene.species[model.species])) {
            EXPECT_LE(reduced * 10, full * 4) << model.name;
        }
    }
}

// The joints a model's foliage hangs from at one LOD: each leaf or blade has its own.
std::set<uint32_t> foliageJoints(const pf::PlantModelPool& pool, const pf::PlantModelInfo& model, uint32_t lod) {
    const pf::MeshRange& range = model.meshes[lod][DRAW_FOLIAGE];
    std::set<uint32_t> joints;
    for (uint32_t i = 0; i < range.indexCount; ++i)
        joints.insert(pool.vertices[range.vertexOffset + pool.indices[range.firstIndex + i]].joint.x);
    return joints;
}

TEST(PlantModels, PlantWithFewLeavesKeepsEveryLeafAtLod1) {
    // Six leaves (data/plants/leafy_plant.lsys): LOD1 must not thin them.
    const pf::PlantModelPool pool = pf::buildPlantModels(sceneOf(kData / "plants" / "leafy_plant.lsys", 1));
    ASSERT_EQ(pool.models.size(), 1u);
    const std::set<uint32_t> full = foliageJoints(pool, pool.models[0], LOD_FULL);
    ASSERT_FALSE(full.empty());
    EXPECT_EQ(foliageJoints(pool, pool.models[0], LOD_REDUCED), full);
}

// A species' cpfg file (.l) is read as cpfg: its tab-indented line goes on
// with the production above (natively it would be a line of its own, and
// an error).
TEST(PlantModels, ASpeciesCpfgFileIsReadAsCpfg) {
    std::filesystem::create_directories(kOutput);
    const std::filesystem::path file = kOutput / "cpfg_probe.l";
    std::ofstream(file) << "derivationlength: 3\nAxiom: A\nA --> F[+A]\n\t[-A]FA\nhomomorphism\nendlsystem\n";
    const pf::PlantModelPool pool = pf::buildPlantModels(sceneOf(file, 1));
    ASSERT_EQ(pool.models.size(), 1u);
    EXPECT_GT(pool.models[0].meshes[LOD_FULL][DRAW_BARK].indexCount, 0u);
}

// A species' warnings reach the pool with the species' name and the file's
// line and column; a plant without any leaves the pool's warnings empty.
TEST(PlantModels, ASpeciesWarningsNameTheSpeciesFileLineAndColumn) {
    const std::filesystem::path cut = writePlant("cut_probe.l", "derivation length: 1\nAxiom: A\nA --> F//turn\n");
    const pf::PlantModelPool pool = pf::buildPlantModels(sceneOf(cut, 1));
    EXPECT_NE(pool.warnings.find("species 'probe': " + cut.string() + ":3:"), std::string::npos) << pool.warnings;
    EXPECT_NE(pool.warnings.find("warning:"), std::string::npos) << pool.warnings;
    EXPECT_EQ(defaultPool().warnings, "");
}

TEST(PlantModels, LeafySpeciesHaveFoliageAtBothLods) {
    const pf::PlantModelPool& pool = defaultPool();
    for (const pf::PlantModelInfo& model : pool.models) {
        EXPECT_GT(model.meshes[LOD_FULL][DRAW_FOLIAGE].indexCount, 0u) << model.name;
        EXPECT_GT(model.meshes[LOD_REDUCED][DRAW_FOLIAGE].indexCount, 0u) << model.name;
    }
}

TEST(PlantModels, BoundsContainEveryVertex) {
    const pf::PlantModelPool& pool = defaultPool();
    for (const pf::PlantModelInfo& model : pool.models) {
        const glm::vec3 centre(model.gpu.sphere), lo(model.gpu.boxMin), hi(model.gpu.boxMax);
        forEachMesh(model, [&](uint32_t, uint32_t, const pf::MeshRange& range) {
            for (uint32_t i = 0; i < range.indexCount; ++i) {
                const glm::vec3 p(pool.vertices[range.vertexOffset + pool.indices[range.firstIndex + i]].position);
                ASSERT_TRUE(glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi)))
                    << model.name;
                ASSERT_LE(glm::distance(p, centre), model.gpu.sphere.w * 1.0001f) << model.name;
            }
        });
    }
}

TEST(PlantModels, ScaledHeightMatchesTheSpecies) {
    const pf::Scene& scene = defaultScene();
    const pf::PlantModelPool& pool = defaultPool();
    for (const pf::PlantModelInfo& model : pool.models) {
        const std::optional<float> height = scene.species[model.species].height;
        if (!height) continue;
        float top = 0.0f;
        for (uint32_t drawClass = 0; drawClass < pf::kMeshClassCount; ++drawClass) {
            const pf::MeshRange& range = model.meshes[LOD_FULL][drawClass];
            for (uint32_t i = 0; i < range.indexCount; ++i)
                top = std::max(top, pool.vertices[range.vertexOffset + pool.indices[range.firstIndex + i]].position.y);
        }
        EXPECT_NEAR(top, *height, 0.01f * *height) << model.name;
    }
}

TEST(PlantModels, SameSceneGivesTheSamePoolBitForBit) {
    const pf::PlantModelPool& first = defaultPool();
    const pf::PlantModelPool second = pf::buildPlantModels(defaultScene());
    ASSERT_EQ(first.vertices.size(), second.vertices.size());
    ASSERT_EQ(first.indices, second.indices);
    EXPECT_EQ(
        std::memcmp(first.vertices.data(), second.vertices.data(), first.vertices.size() * sizeof(gpu::FieldVertex)),
        0);
    ASSERT_EQ(first.models.size(), second.models.size());
    for (size_t m = 0; m < first.models.size(); ++m) {
        EXPECT_EQ(first.models[m].meshes, second.models[m].meshes);
        EXPECT_EQ(std::memcmp(&first.models[m].gpu, &second.models[m].gpu, sizeof(gpu::PlantModel)), 0);
    }
}

// The renderer's pool keeps no plants; a pool that keeps them is otherwise
// the same, and each kept plant, baked again and scaled by its kept scale,
// is its model's meshes bit for bit, colours with the species' overrides.
TEST(PlantModels, KeptPlantsBakeAgainToTheirModels) {
    const pf::PlantModelPool& dropped = defaultPool();
    EXPECT_TRUE(dropped.assets.empty());
    const pf::PlantModelPool kept =
        pf::buildPlantModels(defaultScene(), {}, lsys::machineMemoryBudget(), pf::ModelAssets::Keep);
    ASSERT_EQ(kept.assets.size(), kept.models.size());
    ASSERT_EQ(kept.indices, dropped.indices);
    ASSERT_EQ(kept.vertices.size(), dropped.vertices.size());
    EXPECT_EQ(
        std::memcmp(kept.vertices.data(), dropped.vertices.data(), kept.vertices.size() * sizeof(gpu::FieldVertex)), 0);
    for (size_t m = 0; m < kept.models.size(); ++m) {
        const pf::PlantModelAsset& plant = kept.assets[m];
        const auto lods = lsys::drawnLods(plant.asset);
        forEachMesh(kept.models[m], [&](uint32_t lod, uint32_t drawClass, const pf::MeshRange& range) {
            const lsys::DrawnMesh& mesh = lods[lod][drawClass];
            ASSERT_EQ(range.indexCount, mesh.indices.size()) << kept.models[m].name;
            for (size_t i = 0; i < mesh.vertices.size(); ++i) {
                const gpu::FieldVertex& v = kept.vertices[range.vertexOffset + i];
                const lsys::DrawnVertex& d = mesh.vertices[i];
                ASSERT_EQ(glm::vec3(v.position), d.position * plant.scale) << kept.models[m].name << " vertex " << i;
                ASSERT_EQ(glm::vec3(v.albedo), plant.asset.materials.at(d.material).albedo);
            }
        });
    }
}

TEST(PlantModels, SyntaxErrorNamesSpeciesFileLineAndColumn) {
    const std::filesystem::path path = writePlant("broken.lsys", "derivation length: 2\nAxiom: A\nA --> F(1,\n");
    try {
        pf::buildPlantModels(sceneOf(path, 1));
        FAIL() << "a broken L-system built";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("probe"), std::string::npos) << message;
        EXPECT_NE(message.find(path.string() + ":3:"), std::string::npos) << message;
    }
}

TEST(PlantModels, DerivationOverTheModuleBudgetFailsNamingTheScenesWayOut) {
    const std::filesystem::path path = writePlant("explosive.lsys", "derivation length: 40\nAxiom: F\nF --> FF\n");
    try {
        pf::buildPlantModels(sceneOf(path, 1));
        FAIL() << "a derivation past the budget built";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("module budget exceeded"), std::string::npos) << message;
        // The scene's remedy, not a flag of another tool.
        EXPECT_NE(message.find("fewer \"steps\""), std::string::npos) << message;
        EXPECT_EQ(message.find("--max-modules"), std::string::npos) << message;
    }
}

TEST(PlantModels, StochasticVariantsAreDistinctMeshes) {
    const pf::PlantModelPool pool = pf::buildPlantModels(sceneOf(kData / "plants" / "stochastic_bush.lsys", 3));
    ASSERT_EQ(pool.models.size(), 3u);
    std::set<std::vector<float>> meshes;
    for (const pf::PlantModelInfo& model : pool.models) {
        const pf::MeshRange& range = model.meshes[LOD_FULL][DRAW_BARK];
        const uint32_t vertices = verticesOf(pool, range);
        std::vector<float> positions;
        for (uint32_t i = 0; i < vertices; ++i)
            for (int k = 0; k < 3; ++k) positions.push_back(pool.vertices[range.vertexOffset + i].position[k]);
        meshes.insert(positions);
    }
    EXPECT_EQ(meshes.size(), 3u);
}

// Each variant within the budget, all of them together past it: the pool is
// counted too, before it grows, so the run is refused by name instead of
// climbing to the machine's limit (1 024 variants of a matrix oak did).
TEST(PlantModels, ModelsTogetherPastTheBudgetAreRefusedBeforeThePoolGrowsPastIt) {
    const pf::Scene one = sceneOf(kData / "plants" / "stochastic_bush.lsys", 1);
    const pf::PlantModelPool single = pf::buildPlantModels(one);
    const uint64_t modelBytes = single.vertices.size() * sizeof(gpu::FieldVertex) +
                                single.indices.size() * sizeof(uint32_t) +
                                single.joints.size() * sizeof(gpu::JointParams);
    const lsys::MemoryBudget budget{modelBytes * 20};
    EXPECT_NO_THROW(pf::buildPlantModels(sceneOf(kData / "plants" / "stochastic_bush.lsys", 4), {}, budget));
    try {
        pf::buildPlantModels(sceneOf(kData / "plants" / "stochastic_bush.lsys", 64), {}, budget);
        FAIL() << "64 variants of about 1/20 of the budget each were built";
    } catch (const lsys::MemoryBudgetError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("memory budget: plant models (probe#"), std::string::npos) << message;
        EXPECT_NE(message.find("before it) needs"), std::string::npos) << message;
    }
}

} // namespace
