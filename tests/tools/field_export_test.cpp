// plantfield --export and --export-placements (tools/plantfield/field_export.h):
// the exporter called directly on a small scene's field, read back with
// tinygltf, and the command line, run without any Vulkan driver. The Khronos
// validator runs on the command line's files in ctest (tests/tools/CMakeLists.txt).
#include "bad_invocation.h"
#include "run_command.h"

#include "field_export.h"

#include "engine/scene/scene.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

const std::string kPlantfield = PLANTFIELD_BIN;
const std::string kScene = std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json";
constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

fs::path scratchDir(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "field_export" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

const FieldContent& smallField() {
    static const FieldContent content =
        buildFieldContent(loadScene(kScene), std::nullopt, {}, lsys::machineMemoryBudget(), ModelAssets::Keep);
    return content;
}

tinygltf::Model load(const fs::path& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                                               : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
    EXPECT_TRUE(ok) << path << ": " << error;
    return model;
}

// An accessor's floats, `components` a element.
std::vector<float> floatsOf(const tinygltf::Model& model, int index, size_t components) {
    const tinygltf::Accessor& accessor = model.accessors.at(size_t(index));
    EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
    const unsigned char* data =
        model.buffers.at(size_t(view.buffer)).data.data() + view.byteOffset + accessor.byteOffset;
    std::vector<float> values(accessor.count * components);
    std::memcpy(values.data(), data, values.size() * sizeof(float));
    return values;
}

struct Placement {
    std::string species, model;
    std::vector<float> numbers; // x y z qx qy qz qw scale
};

std::vector<Placement> readCsv(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "species,model,x,y,z,qx,qy,qz,qw,scale");
    std::vector<Placement> rows;
    while (std::getline(in, line)) {
        std::stringstream fields(line);
        Placement& row = rows.emplace_back();
        std::getline(fields, row.species, ',');
        std::getline(fields, row.model, ',');
        for (std::string field; std::getline(fields, field, ',');) row.numbers.push_back(std::stof(field));
        EXPECT_EQ(row.numbers.size(), 8u) << line;
    }
    return rows;
}

// The model nodes of the default scene's root, by name, and the terrain.
std::map<std::string, const tinygltf::Node*> childrenByName(const tinygltf::Model& model) {
    std::map<std::string, const tinygltf::Node*> children;
    const tinygltf::Node& root = model.nodes.at(size_t(model.scenes.at(0).nodes.at(0)));
    for (int child : root.children) children[model.nodes.at(size_t(child)).name] = &model.nodes.at(size_t(child));
    return children;
}

TEST(FieldExport, InstancedFieldHasOneMeshAndNodePerModelAndEveryPlant) {
    const FieldContent& field = smallField();
    const fs::path dir = scratchDir("instanced");
    const FieldExportSummary summary = exportField(field, dir / "field.glb");
    exportPlacements(field, dir / "field.csv");
    const size_t models = field.models.models.size();
    ASSERT_GE(models, 3u);
    EXPECT_EQ(summary.plants, field.plants.size());

    const tinygltf::Model gltf = load(dir / "field.glb");
    EXPECT_EQ(gltf.meshes.size(), models + 1); // every model, and the terrain
    EXPECT_EQ(gltf.nodes.size(), models + 2);  // the root, the terrain and one node a model
    ASSERT_EQ(gltf.extensionsUsed, std::vector<std::string>{kInstancing});
    EXPECT_TRUE(gltf.extensionsRequired.empty()); // loaders without it still read the file

    // Every model's TRANSLATION, ROTATION and SCALE are its plants in the placements file, in order.
    std::map<std::string, std::vector<Placement>> placementsOf;
    for (Placement& row : readCsv(dir / "field.csv")) placementsOf[row.model].push_back(row);
    const auto nodes = childrenByName(gltf);
    ASSERT_TRUE(nodes.count("terrain"));
    size_t instances = 0;
    for (const PlantModelInfo& info : field.models.models) {
        ASSERT_TRUE(nodes.count(info.name)) << info.name;
        const tinygltf::Node& node = *nodes.at(info.name);
        EXPECT_GE(node.mesh, 0);
        EXPECT_EQ(gltf.meshes.at(size_t(node.mesh)).name, info.name);
        ASSERT_TRUE(node.extensions.count(kInstancing)) << info.name;
        const tinygltf::Value& attributes = node.extensions.at(kInstancing).Get("attributes");
        const std::vector<float> t = floatsOf(gltf, attributes.Get("TRANSLATION").GetNumberAsInt(), 3);
        const std::vector<float> r = floatsOf(gltf, attributes.Get("ROTATION").GetNumberAsInt(), 4);
        const std::vector<float> s = floatsOf(gltf, attributes.Get("SCALE").GetNumberAsInt(), 3);
        const std::vector<Placement>& rows = placementsOf[info.name];
        ASSERT_EQ(t.size(), rows.size() * 3) << info.name;
        ASSERT_EQ(r.size(), rows.size() * 4);
        ASSERT_EQ(s.size(), rows.size() * 3);
        for (size_t i = 0; i < rows.size(); ++i) {
            for (size_t k = 0; k < 3; ++k) EXPECT_EQ(t[3 * i + k], rows[i].numbers[k]) << info.name << " plant " << i;
            for (size_t k = 0; k < 4; ++k) EXPECT_EQ(r[4 * i + k], rows[i].numbers[3 + k]);
            for (size_t k = 0; k < 3; ++k) EXPECT_EQ(s[3 * i + k], rows[i].numbers[7]);
        }
        instances += rows.size();
    }
    EXPECT_EQ(instances, field.plants.size());
}

TEST(FieldExport, PlacementsMatchTheFieldExactly) {
    const FieldContent& field = smallField();
    const fs::path dir = scratchDir("placements");
    exportPlacements(field, dir / "p.csv");
    exportPlacements(field, dir / "p.json");
    const std::vector<Placement> rows = readCsv(dir / "p.csv");
    std::ifstream jsonFile(dir / "p.json");
    const nlohmann::json json = nlohmann::json::parse(jsonFile);
    ASSERT_EQ(rows.size(), field.plants.size());
    ASSERT_EQ(json.size(), field.plants.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        const PlantInstance& plant = field.plants[i];
        const glm::quat q = yawRotation(plant.rotation);
        const std::vector<float> expected{plant.position.x, plant.position.y, plant.position.z, q.x, q.y, q.z, q.w,
                                          plant.scale};
        EXPECT_EQ(rows[i].species, field.scene.species[plant.species].name);
        EXPECT_EQ(rows[i].model, field.models.models[field.models.modelOf(plant.species, plant.variant)].name);
        EXPECT_EQ(rows[i].numbers, expected) << "plant " << i; // full precision: the same floats
        EXPECT_EQ(json[i]["species"].get<std::string>(), rows[i].species);
        EXPECT_EQ(json[i]["model"].get<std::string>(), rows[i].model);
        size_t k = 0;
        for (const char* key : {"x", "y", "z", "qx", "qy", "qz", "qw", "scale"})
            EXPECT_EQ(json[i][key].get<float>(), expected[k++]) << key;
    }
}

TEST(FieldExport, YawRotationTurnsAsTheRenderer) {
    // field_common.glsl yawMatrix: +x goes to (cos, 0, -sin).
    const float yaw = 0.7f;
    const glm::vec3 x = yawRotation(yaw) * glm::vec3(1, 0, 0);
    EXPECT_NEAR(x.x, std::cos(yaw), 1e-6f);
    EXPECT_NEAR(x.y, 0.0f, 1e-6f);
    EXPECT_NEAR(x.z, -std::sin(yaw), 1e-6f);
}

TEST(FieldExport, WithoutGpuInstancingEveryPlantIsANode) {
    const FieldContent& field = smallField();
    const fs::path dir = scratchDir("plain");
    FieldExportOptions options;
    options.gpuInstancing = false;
    const FieldExportSummary summary = exportField(field, dir / "field.gltf", options);
    const tinygltf::Model gltf = load(dir / "field.gltf");
    EXPECT_TRUE(gltf.extensionsUsed.empty());
    const size_t models = field.models.models.size();
    EXPECT_EQ(gltf.meshes.size(), models + 1);
    // The root, the terrain, a group a model and a node a plant.
    EXPECT_EQ(gltf.nodes.size(), 2 + models + field.plants.size());
    EXPECT_EQ(summary.nodes, gltf.nodes.size());
    std::map<int, size_t> plantsOfMesh;
    for (const tinygltf::Node& node : gltf.nodes) {
        EXPECT_TRUE(node.extensions.empty());
        if (node.mesh >= 0 && node.name != "terrain") ++plantsOfMesh[node.mesh];
    }
    std::map<int, size_t> expected;
    for (const PlantInstance& plant : field.plants)
        ++expected[int(field.models.modelOf(plant.species, plant.variant)) + 1];
    EXPECT_EQ(plantsOfMesh, expected); // mesh 0 is the terrain, then the models in order

    // The hand-placed tree at (8, -5), turned 90° and 1.5 times as large.
    bool found = false;
    for (const tinygltf::Node& node : gltf.nodes) {
        if (node.scale.empty()) continue;
        found = true;
        EXPECT_EQ(node.scale, (std::vector<double>{1.5, 1.5, 1.5}));
        ASSERT_EQ(node.translation.size(), 3u);
        EXPECT_NEAR(node.translation[0], 8.0, 1e-5);
        EXPECT_NEAR(node.translation[2], -5.0, 1e-5);
        ASSERT_EQ(node.rotation.size(), 4u);
        EXPECT_NEAR(node.rotation[1], std::sin(0.25 * 3.14159265358979), 1e-6);
    }
    EXPECT_TRUE(found);
}

// The test scene with its first species drawing data/plants/PLANT at its own
// size (no height, steps or material overrides), one variant.
Scene sceneDrawing(const std::string& plant) {
    Scene scene = loadScene(kScene);
    Species& species = scene.species.at(0);
    species.lsystem = fs::path(PLANTFIELD_DATA_DIR) / "plants" / plant;
    species.variants = 1;
    species.steps.reset();
    species.height.reset();
    species.materials.clear();
    return scene;
}

// Every POSITION of every mesh of the file.
std::vector<glm::vec3> allPositions(const tinygltf::Model& gltf) {
    std::vector<glm::vec3> positions;
    for (const tinygltf::Mesh& mesh : gltf.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            const std::vector<float> p = floatsOf(gltf, primitive.attributes.at("POSITION"), 3);
            for (size_t i = 0; i < p.size(); i += 3) positions.emplace_back(p[i], p[i + 1], p[i + 2]);
        }
    return positions;
}

bool lexicographic(const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

// `lsys export`'s drawn form and the field's LOD0 come from one bake
// (lsystem/mesh/drawn_mesh.h): the spruce (bark tubes, needle ribbons, no leaf
// cards) exported on its own has exactly the vertices of its model's LOD0
// meshes in the field's pool, bit for bit.
TEST(FieldExport, DrawnPlantExportIsTheFieldsLod0) {
    const Scene scene = sceneDrawing("spruce.lsys");
    const PlantModelPool pool = buildPlantModels(scene);
    const PlantModelInfo& model = pool.models.at(pool.modelOf(0, 0));
    std::vector<glm::vec3> drawn;
    for (uint32_t v = model.meshes[LOD_FULL][DRAW_BARK].vertexOffset;
         v < model.meshes[LOD_REDUCED][DRAW_BARK].vertexOffset; ++v)
        drawn.emplace_back(pool.vertices[v].position);
    ASSERT_GT(drawn.size(), 1000u);

    // The species' plant as buildPlantModels derives it: the same file and seed.
    lsys::vlab::PlantFile file = lsys::vlab::loadPlant(scene.species[0].lsystem);
    ASSERT_TRUE(file.parsed.ok());
    lsys::DeriveOptions options;
    options.seed = speciesSeed(scene, 0);
    options.maxModules = 5'000'000;
    const lsys::PlantAsset plant =
        lsys::plantFromGrammar(file.parsed.grammar, lsys::derive(file.parsed.grammar, options),
                               lsys::SurfaceLibrary(lsys::meshDirectoriesFor(scene.species[0].lsystem)));
    const fs::path dir = scratchDir("drawn");
    lsys::exportPlant(plant, dir / "spruce.glb");
    std::vector<glm::vec3> exported = allPositions(load(dir / "spruce.glb"));

    std::sort(drawn.begin(), drawn.end(), lexicographic);
    std::sort(exported.begin(), exported.end(), lexicographic);
    ASSERT_EQ(exported.size(), drawn.size());
    for (size_t i = 0; i < drawn.size(); ++i) ASSERT_EQ(exported[i], drawn[i]) << "vertex " << i;
}

// A field of the leafy bush (leaf cards) scaled to 2 m, its plants kept for the export.
const FieldContent& leafyField() {
    static const FieldContent content = [] {
        Scene scene = sceneDrawing("leafy_bush.lsys");
        scene.species[0].height = 2.0f;
        return buildFieldContent(scene, std::nullopt, {}, lsys::machineMemoryBudget(), ModelAssets::Keep);
    }();
    return content;
}

// The whole-field export writes a leaf card as the leaf outline the shader
// cuts from it: each of the model's LOD0 cards (four vertices of kind leaf)
// becomes leafOutline()'s vertices, on the card's plane within the card.
TEST(FieldExport, LeafCardsAreLeafOutlines) {
    const FieldContent& field = leafyField();
    const PlantModelPool& pool = field.models;
    const PlantModelInfo& model = pool.models.at(pool.modelOf(0, 0));
    const MeshRange& foliage = model.meshes[LOD_FULL][DRAW_FOLIAGE];
    size_t cardVertices = 0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (uint32_t v = foliage.vertexOffset; v < model.meshes[LOD_REDUCED][DRAW_BARK].vertexOffset; ++v)
        if (pool.vertices[v].albedo.w == SURFACE_LEAF) {
            ++cardVertices;
            lo = glm::min(lo, glm::vec3(pool.vertices[v].position));
            hi = glm::max(hi, glm::vec3(pool.vertices[v].position));
        }
    ASSERT_GT(cardVertices, 0u);
    ASSERT_EQ(cardVertices % 4, 0u);

    const fs::path dir = scratchDir("leaves");
    exportField(field, dir / "field.glb");
    const tinygltf::Model gltf = load(dir / "field.glb");
    size_t leafVertices = 0;
    for (const tinygltf::Mesh& mesh : gltf.meshes) {
        if (mesh.name != model.name) continue;
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            if (gltf.materials.at(size_t(primitive.material)).name.rfind("leaf ", 0) != 0) continue;
            EXPECT_TRUE(gltf.materials.at(size_t(primitive.material)).doubleSided);
            const std::vector<float> p = floatsOf(gltf, primitive.attributes.at("POSITION"), 3);
            leafVertices += p.size() / 3;
            for (size_t i = 0; i < p.size(); i += 3) { // inside the cards' box
                const glm::vec3 q(p[i], p[i + 1], p[i + 2]);
                ASSERT_TRUE(glm::all(glm::greaterThanEqual(q, lo - 1e-5f)) &&
                            glm::all(glm::lessThanEqual(q, hi + 1e-5f)));
            }
        }
    }
    EXPECT_EQ(leafVertices, cardVertices / 4 * lsys::leafOutline().uvs.size());
}

// Every model is its plant baked as `lsys export` bakes one (leaf cards as
// their outlines, bark and blades as the field's LOD0: the test above) and
// scaled as the model: the same positions bit for bit, however the plant's
// triangles look. Sorted, as the field's file writes a vertex where a
// triangle first uses it.
TEST(FieldExport, EveryModelIsItsPlantAsLsysExportsIt) {
    for (const FieldContent* field : {&smallField(), &leafyField()}) {
        const fs::path dir = scratchDir("as_lsys");
        exportField(*field, dir / "field.glb");
        const tinygltf::Model gltf = load(dir / "field.glb");
        const PlantModelPool& pool = field->models;
        ASSERT_EQ(pool.assets.size(), pool.models.size());
        for (size_t m = 0; m < pool.models.size(); ++m) {
            const PlantModelAsset& plant = pool.assets[m];
            lsys::exportPlant(plant.asset, dir / "plant.glb");
            std::vector<glm::vec3> expected = allPositions(load(dir / "plant.glb"));
            for (glm::vec3& p : expected) p *= plant.scale;
            std::vector<glm::vec3> exported;
            for (const tinygltf::Mesh& mesh : gltf.meshes) {
                if (mesh.name != pool.models[m].name) continue;
                for (const tinygltf::Primitive& primitive : mesh.primitives) {
                    const std::vector<float> p = floatsOf(gltf, primitive.attributes.at("POSITION"), 3);
                    for (size_t i = 0; i < p.size(); i += 3) exported.emplace_back(p[i], p[i + 1], p[i + 2]);
                }
            }
            std::sort(expected.begin(), expected.end(), lexicographic);
            std::sort(exported.begin(), exported.end(), lexicographic);
            ASSERT_GT(exported.size(), 0u) << pool.models[m].name;
            ASSERT_EQ(exported.size(), expected.size()) << pool.models[m].name;
            for (size_t i = 0; i < exported.size(); ++i)
                ASSERT_EQ(exported[i], expected[i]) << pool.models[m].name << " vertex " << i;
        }
    }
}

// The memory check counts at least what is written: a budget of the file's
// own size is refused, before anything is written.
TEST(FieldExport, MemoryCheckCountsAtLeastTheFile) {
    const fs::path dir = scratchDir("memory");
    exportField(leafyField(), dir / "field.glb");
    FieldExportOptions options;
    options.memory.limitBytes = fs::file_size(dir / "field.glb");
    EXPECT_THROW(exportField(leafyField(), dir / "again.glb", options), lsys::MemoryBudgetError);
    EXPECT_FALSE(fs::exists(dir / "again.glb"));
}

// Exporting needs the models' plants: a field built for rendering alone is refused by name.
TEST(FieldExport, RefusesAFieldBuiltWithoutItsPlants) {
    const fs::path dir = scratchDir("no_plants");
    const FieldContent field = buildFieldContent(sceneDrawing("leafy_bush.lsys"));
    EXPECT_TRUE(field.models.assets.empty());
    try {
        exportField(field, dir / "field.glb");
        ADD_FAILURE() << "exported without the plants";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("ModelAssets::Keep"), std::string::npos) << error.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(FieldExport, RefusesUnknownExtensionsWithoutWriting) {
    const fs::path dir = scratchDir("refused");
    EXPECT_THROW(exportField(smallField(), dir / "field.obj"), std::runtime_error);
    EXPECT_THROW(exportPlacements(smallField(), dir / "field.txt"), std::runtime_error);
    EXPECT_THROW(exportField(smallField(), dir / "missing" / "field.glb"), std::runtime_error);
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(FieldExportCli, ExportsWithoutAnyVulkanDriver) {
    const fs::path dir = scratchDir("cli");
    // No ICD at all: creating a Vulkan instance or device would fail.
    const CommandResult r = runCommand("VK_ICD_FILENAMES=/nonexistent VK_DRIVER_FILES=/nonexistent " + kPlantfield +
                                       " " + kScene + " --export " + (dir / "field.glb").string() +
                                       " --export-placements " + (dir / "field.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(dir / "field.glb"));
    EXPECT_TRUE(fs::is_regular_file(dir / "field.json"));
    EXPECT_EQ(load(dir / "field.glb").meshes.size(), smallField().models.models.size() + 1);
    EXPECT_NE(r.output.find("EXT_mesh_gpu_instancing"), std::string::npos) << r.output;
}

class FieldExportBadFlags : public ::testing::TestWithParam<BadInvocation> {};

TEST_P(FieldExportBadFlags, FailsClearlyWithoutWriting) {
    expectFailsClearlyWithoutWriting(kPlantfield, GetParam(), scratchDir(std::string("bad-") + GetParam().name), "out");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FieldExportBadFlags,
    ::testing::Values(BadInvocation{"ExportAsObj", "--export OUT.obj", "expected a .glb or .gltf"},
                      BadInvocation{"PlacementsAsTxt", "--export-placements OUT.txt", "expected a .csv or .json"},
                      BadInvocation{"NoGpuInstancingAlone", "--capture OUT.png --no-gpu-instancing",
                                    "--no-gpu-instancing needs --export"},
                      BadInvocation{"ExportWithCapture", "--export OUT.glb --capture x.png", "mode of their own"},
                      BadInvocation{"ExportIntoMissingFolder", "--export /nonexistent-dir/f.glb", "does not exist"}),
    invocationName);

} // namespace
} // namespace pf::test
