// The instanced form (lsystem/export/graph_export.h) against the flat export of the
// same plant: one mesh per object that draws, the node tree mirroring the
// graph, and the same triangles in the same places once the tree is expanded.
#include "lsystem/export/graph_export.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "../lsystem/test_support.h"
#include "gltf_reading.h"
#include "lsystem/export/plant_export.h"
#include "sample_plants.h"

namespace {

namespace fs = std::filesystem;
using plantfield::test::containsPoint;
using plantfield::test::loadGltf;
using plantfield::test::sceneTriangleCorners;

using GraphExport = plantfield::test::ExportDirTest;

lsys::InstanceGraph graphOfFile(const std::string& file, std::optional<int> steps,
                                const lsys::SurfaceLibrary& surfaces) {
    const lsys::Grammar grammar = lsys::test::loadOk(file);
    lsys::BGrammarOptions options;
    options.steps = steps;
    options.interpreted = true;
    return lsys::buildInstanceGraph(lsys::buildBGrammar(grammar, options), grammar, {}, surfaces);
}

// Objects placing a primitive with something to draw themselves.
size_t objectsThatDraw(const lsys::InstanceGraph& graph) {
    size_t count = 0;
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        const auto items = graph.itemsOf(object);
        count += std::any_of(items.begin(), items.end(), [&](const lsys::GraphItem& item) {
            if (item.kind != lsys::GraphItem::Kind::Primitive) return false;
            const lsys::GraphPrimitive& p = graph.primitives[item.index];
            return lsys::isDrawable(
                lsys::Primitive{p.frame, p.kind, p.material, -1, p.shape, p.length, p.startRadius, p.endRadius});
        });
    }
    return count;
}

// About `samples` corners of `from`, each found in `in` within `tolerance`.
void expectSampledCornersIn(const std::vector<glm::vec3>& from, const std::vector<glm::vec3>& in, float tolerance,
                            size_t samples = 40) {
    const size_t step = std::max<size_t>(1, from.size() / samples);
    for (size_t i = 0; i < from.size(); i += step)
        ASSERT_TRUE(containsPoint(in, from[i], tolerance))
            << "corner " << i << ": " << from[i].x << ' ' << from[i].y << ' ' << from[i].z;
}

lsys::GraphExportOptions turtleGeometry() {
    lsys::GraphExportOptions options;
    options.geometry = lsys::ExportGeometry::Turtle;
    return options;
}

// Exports the graph and its flattened plant with the same geometry and
// compares what they draw.
void expectSameDrawingAsFlat(const lsys::InstanceGraph& graph, const lsys::SurfaceLibrary& surfaces,
                             const fs::path& dir, const lsys::GraphExportOptions& options = turtleGeometry()) {
    const lsys::GraphExportSummary summary = lsys::exportInstanceGraph(graph, surfaces, dir / "graph.glb", options);
    lsys::ExportOptions flatOptions;
    flatOptions.geometry = options.geometry;
    flatOptions.segments = options.segments;
    flatOptions.detail = options.detail;
    const lsys::PlantAsset plant = lsys::flatten(graph, surfaces);
    lsys::exportPlant(plant, dir / "flat.glb", flatOptions);

    const tinygltf::Model instanced = loadGltf(dir / "graph.glb"), flat = loadGltf(dir / "flat.glb");
    EXPECT_GT(instanced.meshes.size(), 0u);
    EXPECT_EQ(instanced.meshes.size(), objectsThatDraw(graph));
    EXPECT_EQ(instanced.meshes.size(), summary.meshes);
    EXPECT_EQ(instanced.nodes.size(), summary.nodes);
    EXPECT_EQ(summary.nodes, lsys::graphExportNodeCount(graph));
    EXPECT_EQ(instanced.materials.size(), flat.materials.size());
    for (size_t m = 0; m < std::min(instanced.materials.size(), flat.materials.size()); ++m) {
        EXPECT_EQ(instanced.materials[m].name, flat.materials[m].name);
        EXPECT_EQ(instanced.materials[m].doubleSided, flat.materials[m].doubleSided);
    }
    const std::vector<glm::vec3> graphCorners = sceneTriangleCorners(instanced),
                                 flatCorners = sceneTriangleCorners(flat);
    ASSERT_EQ(graphCorners.size(), flatCorners.size()); // the same triangles drawn
    expectSampledCornersIn(graphCorners, flatCorners, 1e-4f);
    expectSampledCornersIn(flatCorners, graphCorners, 1e-4f);
}

TEST_F(GraphExport, DataPlantsDrawWhatTheFlatFormDraws) {
    const std::pair<const char*, std::optional<int>> plants[] = {
        {"plants/fractal_bush.lsys", 4},                              // one object draws, shared by 512 nodes
        {"plants/monopodial_tree.lsys", std::nullopt},                // `$` and widths
        {"plants/dialects/robbins_first_example.lsys", std::nullopt}, // polygons
        {"plants/stochastic_bush.lsys", std::nullopt},
    };
    for (const auto& [file, steps] : plants) {
        SCOPED_TRACE(file);
        const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(lsys::test::dataPath(file)));
        expectSameDrawingAsFlat(graphOfFile(file, steps, surfaces), surfaces, dir);
    }
}

TEST_F(GraphExport, EveryPrimitiveKindDrawsWhatTheFlatFormDraws) {
    expectSameDrawingAsFlat(plantfield::test::sampleGraph(), lsys::SurfaceLibrary{}, dir);
}

// A vlab object's own surfaces (its .s files) come with the grammar's look,
// not from the library: the instanced export draws them as the flat one does.
TEST_F(GraphExport, AnObjectsOwnSurfacesDrawWhatTheFlatFormDraws) {
    lsys::Grammar grammar = lsys::test::parseOk("derivation length: 3\nAxiom: A\nA --> F[+~s(0.5)]A\n");
    lsys::SurfaceMesh triangle;
    triangle.name = "s";
    triangle.positions = {{-0.2f, 0.0f, 0.0f}, {0.2f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    triangle.normals.assign(3, {0.0f, 0.0f, 1.0f});
    triangle.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.5f, 1.0f}};
    triangle.indices = {0, 1, 2};
    grammar.style.look.surfaces = std::make_shared<std::vector<lsys::SurfaceMesh>>(1, triangle);
    lsys::BGrammarOptions options;
    options.interpreted = true;
    const lsys::SurfaceLibrary noMeshFiles;
    const lsys::InstanceGraph graph =
        lsys::buildInstanceGraph(lsys::buildBGrammar(grammar, options), grammar, {}, noMeshFiles);
    expectSameDrawingAsFlat(graph, noMeshFiles, dir);
}

// Without caps a tube has 2·sides triangles per segment however the chains
// are cut, so cutting them at instances keeps the count.
TEST_F(GraphExport, GeneralizedCylindersWithoutCapsDrawTheSameTriangles) {
    lsys::GraphExportOptions options = turtleGeometry();
    options.segments = lsys::SegmentGeometry::GeneralizedCylinders;
    options.detail.segmentCaps = false;
    const lsys::InstanceGraph graph = plantfield::test::sampleGraph();
    lsys::exportInstanceGraph(graph, lsys::SurfaceLibrary{}, dir / "graph.gltf", options);
    lsys::ExportOptions flatOptions;
    flatOptions.geometry = lsys::ExportGeometry::Turtle;
    flatOptions.segments = options.segments;
    flatOptions.detail = options.detail;
    lsys::exportPlant(lsys::flatten(graph), dir / "flat.gltf", flatOptions);
    EXPECT_EQ(sceneTriangleCorners(loadGltf(dir / "graph.gltf")).size(),
              sceneTriangleCorners(loadGltf(dir / "flat.gltf")).size());
}

// The drawn form (the default) bakes each object with the whole plant's
// scale, so its foliage (two-sided materials: leaf outlines, polygons, the
// spruce's needle ribbons) is the flat drawn form's, triangle for triangle.
// (Bark tubes end at each instance, as generalised cylinders do.)
TEST_F(GraphExport, DrawnFoliageIsTheFlatDrawnFoliage) {
    const lsys::SurfaceLibrary spruceSurfaces(lsys::meshDirectoriesFor(lsys::test::dataPath("plants/spruce.lsys")));
    const std::pair<lsys::InstanceGraph, const lsys::SurfaceLibrary*> graphs[] = {
        {plantfield::test::sampleGraph(), &spruceSurfaces},
        {graphOfFile("plants/spruce.lsys", std::nullopt, spruceSurfaces), &spruceSurfaces},
    };
    for (const auto& [graph, surfaces] : graphs) {
        lsys::exportInstanceGraph(graph, *surfaces, dir / "graph.glb");
        lsys::exportPlant(lsys::flatten(graph, *surfaces), dir / "flat.glb");
        const tinygltf::Model instanced = loadGltf(dir / "graph.glb"), flat = loadGltf(dir / "flat.glb");
        size_t foliage = 0;
        for (size_t m = 0; m < flat.materials.size(); ++m) {
            if (!flat.materials[m].doubleSided) continue;
            const std::vector<glm::vec3> graphCorners = sceneTriangleCorners(instanced, int(m)),
                                         flatCorners = sceneTriangleCorners(flat, int(m));
            ASSERT_EQ(graphCorners.size(), flatCorners.size()) << flat.materials[m].name;
            expectSampledCornersIn(graphCorners, flatCorners, 1e-4f);
            expectSampledCornersIn(flatCorners, graphCorners, 1e-4f);
            foliage += flatCorners.size();
        }
        EXPECT_GT(foliage, 0u);
    }
}

// Each instance is a node placed by its own transform below its parent's,
// holding its object's mesh: every instance of an object shares one mesh.
TEST_F(GraphExport, NodesMirrorTheGraph) {
    const lsys::InstanceGraph graph = plantfield::test::sampleGraph();
    lsys::exportInstanceGraph(graph, lsys::SurfaceLibrary{}, dir / "graph.gltf");
    const tinygltf::Model model = loadGltf(dir / "graph.gltf");
    ASSERT_EQ(model.scenes[0].nodes, std::vector<int>{0});
    std::vector<int> meshOfObject(graph.objects.size(), -2);
    size_t checked = 0;
    const auto check = [&](auto& self, uint32_t object, int node) -> void {
        const tinygltf::Node& gltfNode = model.nodes.at(size_t(node));
        if (meshOfObject[object] == -2) meshOfObject[object] = gltfNode.mesh;
        EXPECT_EQ(gltfNode.mesh, meshOfObject[object]) << "object " << object;
        std::vector<const lsys::GraphInstance*> instances;
        for (const lsys::GraphItem& item : graph.itemsOf(object))
            if (item.kind == lsys::GraphItem::Kind::Instance) instances.push_back(&graph.instances[item.index]);
        ASSERT_EQ(gltfNode.children.size(), instances.size()); // every subtree of the sample draws
        for (size_t i = 0; i < instances.size(); ++i) {
            const tinygltf::Node& child = model.nodes.at(size_t(gltfNode.children[i]));
            const glm::vec3 position = instances[i]->frame.position;
            if (position != glm::vec3(0.0f)) {
                ASSERT_EQ(child.translation.size(), 3u);
                EXPECT_NEAR(child.translation[1], position.y, 1e-6);
            }
            ++checked;
            self(self, instances[i]->object, gltfNode.children[i]);
        }
    };
    check(check, graph.root, 0);
    EXPECT_EQ(checked + 1, model.nodes.size());
    EXPECT_GT(model.nodes.size(), model.meshes.size()); // meshes are shared
}

TEST_F(GraphExport, NodeBudgetIsEnforcedBeforeWriting) {
    const lsys::SurfaceLibrary surfaces;
    const lsys::InstanceGraph graph = graphOfFile("plants/fractal_bush.lsys", 9, surfaces);
    EXPECT_EQ(lsys::graphExportNodeCount(graph), 19'173'961u); // 1 + 8 + … + 8^8 nodes for 8^9 segments
    try {
        lsys::exportInstanceGraph(graph, surfaces, dir / "bush.glb");
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find((dir / "bush.glb").string()), std::string::npos) << message;
        EXPECT_NE(message.find("19173961 glTF nodes"), std::string::npos) << message;
        EXPECT_NE(message.find("budget of 1000000"), std::string::npos) << message;
        EXPECT_NE(message.find("--flat"), std::string::npos) << message;
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(GraphExport, ObjIsRefused) {
    try {
        lsys::exportInstanceGraph(plantfield::test::sampleGraph(), lsys::SurfaceLibrary{}, dir / "plant.obj");
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("OBJ is always flat"), std::string::npos) << error.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

} // namespace
