// Predefined surfaces: the built-in leaf and petal, meshes from data/meshes
// read with tinygltf, and clear errors for unknown names and bad files.

#include <filesystem>
#include <fstream>

#include "turtle_test_support.h"

namespace lsys::test {
namespace {

namespace fs = std::filesystem;

void expectWellFormed(const SurfaceMesh& mesh) {
    ASSERT_FALSE(mesh.positions.empty());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
    if (!mesh.normals.empty()) {
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    }
    if (!mesh.uvs.empty()) {
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    }
}

// Built-in surfaces grow from the origin along +Y to 1 and face +Z.
void expectGrowsAlongHeading(const SurfaceMesh& mesh) {
    expectWellFormed(mesh);
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.extend(p);
    EXPECT_NEAR(bounds.min.y, 0.0f, 1e-6f);
    EXPECT_NEAR(bounds.max.y, 1.0f, 1e-6f);
    EXPECT_NEAR(bounds.min.x, -bounds.max.x, 1e-6f); // symmetric about the midrib
    EXPECT_GT(bounds.max.x, 0.2f);
    glm::vec3 facing(0.0f);
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[i]];
        facing += glm::cross(mesh.positions[mesh.indices[i + 1]] - a, mesh.positions[mesh.indices[i + 2]] - a);
    }
    EXPECT_GT(glm::normalize(facing).z, 0.9f);
    for (const glm::vec3& n : mesh.normals) EXPECT_GT(n.z, 0.0f);
}

TEST(LsysSurfaces, BuiltInLeaf) {
    const SurfaceMesh leaf = leafSurface();
    EXPECT_EQ(leaf.name, "leaf");
    expectGrowsAlongHeading(leaf);
}

TEST(LsysSurfaces, BuiltInPetalIsWidestNearTheTip) {
    const SurfaceMesh petal = petalSurface();
    EXPECT_EQ(petal.name, "petal");
    expectGrowsAlongHeading(petal);
    glm::vec3 widest(0.0f);
    for (const glm::vec3& p : petal.positions)
        if (p.x > widest.x) widest = p;
    EXPECT_GT(widest.y, 0.6f);
}

TEST(LsysSurfaces, GltfMeshFromDataMeshes) {
    const SurfaceMesh flower = loadSurfaceFile(dataPath("meshes/flower.gltf"), "flower");
    EXPECT_EQ(flower.name, "flower");
    expectWellFormed(flower);
    EXPECT_EQ(flower.positions.size(), 20u);
    EXPECT_EQ(flower.indices.size(), 30u);
    EXPECT_EQ(flower.normals.size(), 20u);
    EXPECT_TRUE(flower.uvs.empty()); // the file has none
}

TEST(LsysSurfaces, GlbMeshFromDataMeshes) {
    const SurfaceMesh bud = loadSurfaceFile(dataPath("meshes/bud.glb"), "bud");
    expectWellFormed(bud);
    EXPECT_EQ(bud.positions.size(), 6u);
    EXPECT_EQ(bud.indices.size(), 24u);
    EXPECT_TRUE(bud.normals.empty());
    EXPECT_FLOAT_EQ(bud.positions[5].y, 1.0f);
}

TEST(LsysSurfaces, MeshDirectoriesAreFoundAboveThePlantFile) {
    const std::vector<fs::path> directories = meshDirectoriesFor(dataPath("plants/dialects/tree_7_1.crankshaw"));
    ASSERT_FALSE(directories.empty());
    EXPECT_TRUE(fs::equivalent(directories.front(), dataPath("meshes")));
}

TEST(LsysSurfaces, PlantUsesAMeshSurface) {
    const SurfaceLibrary library(meshDirectoriesFor(dataPath("plants/koch_curve.lsys")));
    const PlantAsset plant = plantOf("Axiom: F~flower(0.5)F~bud\n", library);
    ASSERT_EQ(plant.surfaces.size(), 2u);
    EXPECT_EQ(plant.surfaces[0].name, "flower");
    EXPECT_EQ(plant.surfaces[0].positions.size(), 20u);
    EXPECT_EQ(plant.surfaces[1].name, "bud");
    EXPECT_FLOAT_EQ(plant.primitives[1].length, 0.5f);
}

// Runs `work` and returns the SurfaceError's message, failing if there is none.
template <typename Work>
std::string surfaceErrorOf(Work work) {
    try {
        work();
    } catch (const SurfaceError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no SurfaceError";
    return {};
}

struct TemporaryDirectory {
    fs::path path = fs::temp_directory_path() /
                    ("plantfield_surfaces_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TemporaryDirectory() { fs::create_directories(path); }
    ~TemporaryDirectory() { fs::remove_all(path); }
};

TEST(LsysSurfaces, LibraryLoadsEachSurfaceOnce) {
    TemporaryDirectory directory;
    fs::copy_file(dataPath("meshes/flower.gltf"), directory.path / "flower.gltf");
    const SurfaceLibrary library({directory.path});
    const SurfaceMesh& flower = library.surface("flower");
    fs::remove(directory.path / "flower.gltf"); // a second read would fail now
    EXPECT_EQ(&flower, &library.surface("flower"));
    EXPECT_EQ(&library.surface("leaf"), &library.surface("leaf"));
}

TEST(LsysSurfaces, UnknownSurfaceNamesEveryPathTried) {
    TemporaryDirectory directory;
    const SurfaceLibrary library({directory.path});
    const std::string message = surfaceErrorOf([&] { (void)library.surface("fern"); });
    EXPECT_NE(message.find("~fern"), std::string::npos) << message;
    EXPECT_NE(message.find((directory.path / "fern.gltf").string()), std::string::npos) << message;
    EXPECT_NE(message.find((directory.path / "fern.glb").string()), std::string::npos) << message;
}

TEST(LsysSurfaces, UnknownSurfaceWithoutDirectoriesFailsTheInterpretation) {
    const std::string message = surfaceErrorOf([] { (void)plantOf("Axiom: F~sunflower(2)\n"); });
    EXPECT_NE(message.find("~sunflower"), std::string::npos) << message;
    EXPECT_NE(message.find("no mesh directories"), std::string::npos) << message;
}

TEST(LsysSurfaces, BadMeshFilesNameTheFile) {
    TemporaryDirectory directory;
    std::ofstream(directory.path / "broken.gltf") << "{ this is not json";
    std::ofstream(directory.path / "empty.gltf") << R"({"asset": {"version": "2.0"}})";
    std::ofstream(directory.path / "short.glb") << "glTF";
    const SurfaceLibrary library({directory.path});
    for (const char* name : {"broken", "empty", "short"}) {
        SCOPED_TRACE(name);
        const std::string message = surfaceErrorOf([&] { (void)library.surface(name); });
        EXPECT_NE(message.find((directory.path / name).string()), std::string::npos) << message;
    }
    EXPECT_NE(surfaceErrorOf([&] { (void)library.surface("empty"); }).find("no mesh"), std::string::npos);
}

TEST(LsysSurfaces, IndicesPastTheVerticesAreRejected) {
    TemporaryDirectory directory;
    // One triangle whose third index (9) points past the three vertices.
    std::ofstream(directory.path / "bad_index.gltf") << R"({
      "asset": {"version": "2.0"},
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 42, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAkA"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
    })";
    const std::string message =
        surfaceErrorOf([&] { (void)loadSurfaceFile(directory.path / "bad_index.gltf", "bad"); });
    EXPECT_NE(message.find("index"), std::string::npos) << message;
}

// A triangle of three float positions and three short indices, with the
// given replacements spliced into its JSON.
std::string triangleGltf(const std::string& viewExtra, const std::string& accessorExtra) {
    return R"({
      "asset": {"version": "2.0"},
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 42, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36)" +
           viewExtra + R"(}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "min": [0,0,0], "max": [1,1,0])" +
           accessorExtra + R"(},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
    })";
}

std::string meshErrorOf(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    return surfaceErrorOf([&] { (void)loadSurfaceFile(file, "hostile"); });
}

TEST(LsysSurfaces, TheTriangleOfTheHostileCasesIsValid) {
    TemporaryDirectory directory;
    std::ofstream(directory.path / "ok.gltf") << triangleGltf("", R"(, "count": 3)");
    EXPECT_EQ(loadSurfaceFile(directory.path / "ok.gltf", "ok").indices.size(), 3u);
}

TEST(LsysSurfaces, HugeCountsAndOffsetsAreRejectedWithoutOverflow) {
    TemporaryDirectory directory;
    // 2^60 elements of stride 16: stride · count wraps around 2^64.
    EXPECT_NE(meshErrorOf(directory.path / "count.gltf",
                          triangleGltf(R"(, "byteStride": 16)", R"(, "count": 1152921504606846976)"))
                  .find("reaches past"),
              std::string::npos);
    // An offset just below 2^64 wraps the start back before the buffer.
    EXPECT_NE(meshErrorOf(directory.path / "offset.gltf",
                          triangleGltf("", R"(, "count": 3, "byteOffset": 18446744073709551600)"))
                  .find("reaches past"),
              std::string::npos);
    EXPECT_NE(meshErrorOf(directory.path / "view.gltf",
                          triangleGltf(R"(, "byteOffset": 18446744073709551600)", R"(, "count": 3)"))
                  .find("reaches past"),
              std::string::npos);
    EXPECT_NE(meshErrorOf(directory.path / "stride.gltf", triangleGltf(R"(, "byteStride": 4)", R"(, "count": 3)"))
                  .find("stride"),
              std::string::npos);
}

TEST(LsysSurfaces, DeeplyNestedJsonIsRejectedBeforeTinygltfRecurses) {
    TemporaryDirectory directory;
    const std::string deep =
        R"({"asset": {"version": "2.0"}, "extras": )" + std::string(100000, '[') + std::string(100000, ']') + "}";
    EXPECT_NE(meshErrorOf(directory.path / "deep.gltf", deep).find("deeper than"), std::string::npos);
}

TEST(LsysSurfaces, ABufferUriThatIsNotAFileIsRejected) {
    TemporaryDirectory directory;
    fs::create_directory(directory.path / "folder.bin");
    std::string text = triangleGltf("", R"(, "count": 3)");
    const size_t uri = text.find("data:");
    text.replace(uri, text.find('"', uri) - uri, "folder.bin");
    EXPECT_NE(meshErrorOf(directory.path / "folder.gltf", text).find("not a file"), std::string::npos);
}

} // namespace
} // namespace lsys::test
