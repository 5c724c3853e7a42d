#include "lsystem/export/plant_export.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gltf_reading.h"
#include "sample_plants.h"

namespace {

namespace fs = std::filesystem;
using plantfield::test::containsPoint;
using plantfield::test::loadGltf;
using plantfield::test::samplePlant;
using plantfield::test::sceneTriangleCorners;

// Counts for samplePlant() with the default MeshDetail (8 sides, capped;
// sphere 12 × 8), as primitive_mesh_test pins them.
constexpr size_t kBarkVertices = 4 * 36 + 117, kBarkTriangles = 4 * 32 + 168;
constexpr size_t kLeafVertices = 2 * 4 + 6, kLeafTriangles = 2 * 2 + 4;
constexpr size_t kJoints = 5;

class ExportFiles : public plantfield::test::ExportDirTest {
protected:
    std::vector<std::string> filesInDir() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

// The turtle's geometry, whose counts the tests below pin (the default is the drawn form).
lsys::ExportOptions turtleOptions(lsys::SegmentGeometry segments = lsys::SegmentGeometry::Frusta) {
    lsys::ExportOptions options;
    options.geometry = lsys::ExportGeometry::Turtle;
    options.segments = segments;
    return options;
}

size_t meshVertexCount(const tinygltf::Model& model, size_t mesh) {
    return model.accessors.at(size_t(model.meshes.at(mesh).primitives.at(0).attributes.at("POSITION"))).count;
}

size_t meshTriangleCount(const tinygltf::Model& model, size_t mesh) {
    return model.accessors.at(size_t(model.meshes.at(mesh).primitives.at(0).indices)).count / 3;
}

int nodeNamed(const tinygltf::Model& model, const std::string& name) {
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (model.nodes[i].name == name) return int(i);
    return -1;
}

TEST_F(ExportFiles, FlatGltfAndGlbLoadBackWithTheSameCounts) {
    const lsys::PlantAsset plant = samplePlant();
    for (const char* name : {"plant.gltf", "plant.glb"}) {
        SCOPED_TRACE(name);
        lsys::exportPlant(plant, dir / name, turtleOptions());
        const tinygltf::Model model = loadGltf(dir / name);
        ASSERT_EQ(model.materials.size(), 2u);
        EXPECT_EQ(model.materials[1].name, "leaf green");
        EXPECT_FALSE(model.materials[0].doubleSided);
        EXPECT_TRUE(model.materials[1].doubleSided);
        EXPECT_NEAR(model.materials[0].pbrMetallicRoughness.baseColorFactor[0], 0.4, 1e-6);
        EXPECT_EQ(model.materials[0].pbrMetallicRoughness.metallicFactor, 0.0);
        ASSERT_EQ(model.meshes.size(), 2u); // one per material
        EXPECT_EQ(meshVertexCount(model, 0), kBarkVertices);
        EXPECT_EQ(meshTriangleCount(model, 0), kBarkTriangles);
        EXPECT_EQ(meshVertexCount(model, 1), kLeafVertices);
        EXPECT_EQ(meshTriangleCount(model, 1), kLeafTriangles);
        EXPECT_EQ(model.nodes.size(), 1 + 2 + kJoints); // root, a node per mesh, the skeleton

        const std::vector<glm::vec3> corners = sceneTriangleCorners(model);
        EXPECT_EQ(corners.size(), 3 * (kBarkTriangles + kLeafTriangles));
        const glm::vec3 stemTip = plantfield::test::segmentTip(plant, 2);
        EXPECT_TRUE(containsPoint(corners, stemTip + glm::vec3(0, 0.05f, 0), 1e-6f)); // the sphere's top
        EXPECT_TRUE(containsPoint(corners, stemTip + glm::vec3(1, 1, 0), 1e-6f));     // the L's inner corner
    }
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"plant.glb", "plant.gltf"}));
}

TEST_F(ExportFiles, GltfEmbedsItsBuffer) {
    lsys::exportPlant(samplePlant(), dir / "plant.gltf");
    std::ifstream in(dir / "plant.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("data:application/octet-stream;base64,"), std::string::npos);
}

TEST_F(ExportFiles, SkeletonNodesFollowTheJoints) {
    const lsys::PlantAsset plant = samplePlant();
    lsys::exportPlant(plant, dir / "plant.glb");
    const tinygltf::Model model = loadGltf(dir / "plant.glb");
    const int stem = nodeNamed(model, "joint_0"), branch = nodeNamed(model, "joint_3");
    ASSERT_GE(stem, 0);
    const auto& children = model.nodes[size_t(stem)].children;
    EXPECT_NE(std::find(children.begin(), children.end(), branch), children.end());
    EXPECT_EQ(model.scenes[0].nodes.size(), 1u);

    lsys::ExportOptions options;
    options.skeleton = false;
    lsys::exportPlant(plant, dir / "bare.glb", options);
    EXPECT_EQ(loadGltf(dir / "bare.glb").nodes.size(), 1 + 2u); // root, a node per mesh
}

TEST_F(ExportFiles, GeneralizedCylindersReplaceTheSegments) {
    const lsys::PlantAsset plant = samplePlant();
    lsys::exportPlant(plant, dir / "flat.gltf", turtleOptions(lsys::SegmentGeometry::GeneralizedCylinders));
    const tinygltf::Model flat = loadGltf(dir / "flat.gltf");
    EXPECT_EQ(meshVertexCount(flat, 0), 54u + 36u + 117u); // stem chain, branch, sphere
    EXPECT_EQ(meshTriangleCount(flat, 0), 64u + 32u + 168u);
}

TEST_F(ExportFiles, ObjMatchesTheFlatGltf) {
    const lsys::PlantAsset plant = samplePlant();
    lsys::exportPlant(plant, dir / "plant.obj", turtleOptions());
    lsys::exportPlant(plant, dir / "plant.glb", turtleOptions());
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"plant.glb", "plant.mtl", "plant.obj"}));
    const plantfield::test::ObjCounts obj = plantfield::test::readObj(dir / "plant.obj");
    EXPECT_EQ(obj.mtllib, "plant.mtl");
    EXPECT_EQ(obj.positions, kBarkVertices + kLeafVertices);
    EXPECT_EQ(obj.uvs, obj.positions);
    EXPECT_EQ(obj.normals, obj.positions);
    EXPECT_EQ(obj.triangles, kBarkTriangles + kLeafTriangles);
    EXPECT_EQ(obj.materials, (std::vector<std::string>{"bark", "leaf_green"}));
    const std::vector<glm::vec3> gltf = sceneTriangleCorners(loadGltf(dir / "plant.glb"));
    ASSERT_EQ(obj.corners.size(), gltf.size());
    for (size_t i = 0; i < gltf.size(); ++i) ASSERT_EQ(obj.corners[i], gltf[i]) << i; // same order, exact digits

    std::ifstream mtl(dir / "plant.mtl");
    size_t newmtl = 0;
    for (std::string line; std::getline(mtl, line);) newmtl += line.rfind("newmtl ", 0) == 0;
    EXPECT_EQ(newmtl, 2u);
}

TEST_F(ExportFiles, EmptyPlantIsAValidEmptyScene) {
    lsys::exportPlant(lsys::PlantAsset{}, dir / "empty.glb");
    const tinygltf::Model model = loadGltf(dir / "empty.glb");
    EXPECT_EQ(model.nodes.size(), 1u);
    EXPECT_TRUE(model.buffers.empty());
}

// The message names the file and nothing is left behind.
void expectFailure(const lsys::PlantAsset& plant, const fs::path& path, const std::string& reason) {
    try {
        lsys::exportPlant(plant, path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
    }
}

TEST_F(ExportFiles, UnknownExtensionIsRefused) {
    expectFailure(samplePlant(), dir / "plant.stl", "unknown extension '.stl'");
    expectFailure(samplePlant(), dir / "plant", "unknown extension ''");
    EXPECT_TRUE(filesInDir().empty());
}

TEST_F(ExportFiles, UnwritablePathsLeaveNothingBehind) {
    expectFailure(samplePlant(), dir / "missing" / "plant.gltf", "does not exist");
    expectFailure(samplePlant(), dir / "missing" / "plant.obj", "does not exist");
    fs::create_directory(dir / "taken.glb");
    expectFailure(samplePlant(), dir / "taken.glb", "is a folder");
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"taken.glb"}));
}

TEST_F(ExportFiles, InconsistentAssetIsRefusedAndTheOldFileKept) {
    lsys::exportPlant(samplePlant(), dir / "plant.gltf");
    const auto before = fs::file_size(dir / "plant.gltf");
    lsys::PlantAsset plant = samplePlant();
    plant.primitives[2].material = 7;
    expectFailure(plant, dir / "plant.gltf", "primitive 2: material 7 of 2");
    plant = samplePlant();
    plant.joints[0].parent = 2;
    expectFailure(plant, dir / "plant.gltf", "joint 0");
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"plant.gltf"}));
    EXPECT_EQ(fs::file_size(dir / "plant.gltf"), before);
}

} // namespace
