// Images ray traced on the CPU (lsystem/raytrace/render.h): the framed camera
// sees the whole box, the bytes do not depend on the thread count, shadow
// rays darken the ground under a sphere, the graph and its flattened plant
// give the same picture, and the material tables of both forms of a graph.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "../instance_graph/instance_graph_test_support.h"
#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/raytrace/flat_tracer.h"
#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/raytrace/render.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys::test {
namespace {

// Where a point lands in normalised device coordinates ([-1, 1] across the
// image), by glm's look-at and perspective rather than the renderer's rays.
glm::vec3 projected(const PinholeCamera& camera, float aspect, glm::vec3 point) {
    const glm::mat4 view = glm::lookAtRH(camera.position, camera.target, camera.up);
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(camera.fovYDegrees), aspect, 0.01f, 1000.0f);
    const glm::vec4 clip = projection * view * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// The pixel a point lands in.
glm::uvec2 pixelOf(const PinholeCamera& camera, uint32_t width, uint32_t height, glm::vec3 point) {
    const glm::vec3 ndc = projected(camera, float(width) / float(height), point);
    return {uint32_t((ndc.x + 1.0f) * 0.5f * float(width)), uint32_t((1.0f - ndc.y) * 0.5f * float(height))};
}

int brightness(const RenderedImage& image, glm::uvec2 pixel) {
    const uint8_t* p = &image.rgba[(size_t(pixel.y) * image.width + pixel.x) * 4];
    return p[0] + p[1] + p[2];
}

// plantfield's default light (pf::Environment), which the lsys CLI passes.
Lighting defaultLight() {
    return {glm::normalize(glm::vec3(0.51f, 0.62f, 0.60f)),
            {1.9f, 1.8f, 1.6f},
            {0.16f, 0.30f, 0.62f},
            {0.62f, 0.72f, 0.85f},
            {0.13f, 0.22f, 0.055f}};
}

TEST(FramedCamera, EveryCornerOfTheBoxIsInTheImageAndOneIsNearItsEdge) {
    const Bounds boxes[] = {{glm::vec3(-1, 0, -1), glm::vec3(1, 6, 1)},
                            {glm::vec3(-10, 0, -0.5f), glm::vec3(10, 2, 0.5f)},
                            {glm::vec3(3, 4, 5), glm::vec3(3.5f, 4.1f, 9)}};
    const ViewAngles views[] = {{}, {0.0f, 0.0f}, {90.0f, 60.0f}, {-135.0f, -30.0f}};
    for (const Bounds& box : boxes)
        for (const ViewAngles& view : views)
            for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
                const PinholeCamera camera = framedCamera(box, aspect, view, 45.0f, 0.05f);
                float widest = 0.0f;
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::vec3 p{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                      corner & 4 ? box.max.z : box.min.z};
                    const glm::vec3 ndc = projected(camera, aspect, p);
                    EXPECT_LE(std::abs(ndc.x), 0.95f + 1e-4f) << "corner " << corner;
                    EXPECT_LE(std::abs(ndc.y), 0.95f + 1e-4f) << "corner " << corner;
                    EXPECT_GT(ndc.z, 0.0f) << "corner " << corner << " behind the camera";
                    widest = std::max({widest, std::abs(ndc.x), std::abs(ndc.y)});
                }
                // As near as it can be: some corner touches the margin.
                EXPECT_NEAR(widest, 0.95f, 1e-3f);
            }
}

TEST(CameraRay, PassesThroughTheProjectedPoint) {
    const PinholeCamera camera{{1, 2, 8}, {0, 1, 0}, {0, 1, 0}, 50.0f};
    const Ray ray = cameraRay(camera, 200, 100, 30.0f, 80.0f);
    const glm::vec3 point = ray.origin + 5.0f * ray.direction;
    const glm::vec3 ndc = projected(camera, 2.0f, point);
    EXPECT_NEAR((ndc.x + 1.0f) * 100.0f, 30.0f, 1e-3f);
    EXPECT_NEAR((1.0f - ndc.y) * 50.0f, 80.0f, 1e-3f);
    EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
}

// Straight down the look-at basis has no right vector of its own
// (lsystem/common/view_up.h): +x is right and -z is up in the image.
TEST(CameraRay, LookingStraightDownPutsXRightAndMinusZUp) {
    const PinholeCamera camera{{2, 10, 3}, {2, 0, 3}};
    const Ray centre = cameraRay(camera, 200, 100, 100.0f, 50.0f);
    const Ray right = cameraRay(camera, 200, 100, 190.0f, 50.0f);
    const Ray top = cameraRay(camera, 200, 100, 100.0f, 5.0f);
    EXPECT_NEAR(centre.direction.y, -1.0f, 1e-6f);
    EXPECT_GT(right.direction.x, 0.1f);
    EXPECT_NEAR(right.direction.z, 0.0f, 1e-6f);
    EXPECT_LT(top.direction.z, -0.1f);
    EXPECT_NEAR(top.direction.x, 0.0f, 1e-6f);
}

RenderOptions smallImage(const Bounds& bounds, uint32_t width, uint32_t height) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.camera = framedCamera(bounds, float(width) / float(height));
    options.light = defaultLight();
    options.groundHeight = std::min(0.0f, bounds.min.y);
    return options;
}

TEST(RenderImage, TheSameBytesOnOneThreadAndOnThree) {
    const InstanceGraph graph = graphOf(loadOk("plants/fractal_bush.lsys"), 4);
    const GraphTracer tracer = buildGraphTracer(graph);
    const Bounds& bounds = graph.objects[graph.root].bounds;
    RenderOptions options = smallImage(bounds, 96, 64);
    options.samples = 2;
    const float size = glm::length(bounds.max - bounds.min);
    options.threads = 1;
    const RenderedImage one = renderImage(traceOf(tracer), materialsOf(graph), size, options);
    options.threads = 3;
    uint32_t lastRowsDone = 0;
    options.onRow = [&](uint32_t rowsDone) { lastRowsDone = rowsDone; };
    const RenderedImage three = renderImage(traceOf(tracer), materialsOf(graph), size, options);
    EXPECT_EQ(one.rgba, three.rgba);
    EXPECT_EQ(one.cameraRays, 96u * 64u * 2u);
    EXPECT_EQ(three.cameraRays, one.cameraRays);
    EXPECT_EQ(three.shadowRays, one.shadowRays);
    EXPECT_EQ(lastRowsDone, 64u);
}

// A sphere of radius 0.5 a metre above the ground, the sun at 45° along +x:
// its shadow is a disc about (-1, 0, 0).
TEST(RenderImage, TheGroundUnderTheSphereIsInItsShadow) {
    PlantAsset plant;
    plant.materials = defaultPalette();
    plant.primitives.push_back({Frame{glm::vec3(0, 1, 0)}, PrimitiveKind::Sphere, 3, -1, 0, 0.0f, 0.5f, 0.5f});
    const FlatTracer tracer = buildFlatTracer(plant);
    RenderOptions options;
    options.width = 160;
    options.height = 120;
    options.camera = {{0, 4, 6}, {-0.5f, 0, 0}};
    options.light = defaultLight();
    options.light.sunDirection = glm::normalize(glm::vec3(1, 1, 0));
    options.groundHeight = 0.0f;
    const glm::uvec2 shadowed = pixelOf(options.camera, 160, 120, {-1, 0, 0});
    const glm::uvec2 beside = pixelOf(options.camera, 160, 120, {-1, 0, 1.5f});
    const glm::uvec2 sphereTop = pixelOf(options.camera, 160, 120, {0, 1.5f, 0});

    const RenderedImage image = renderImage(traceOf(tracer), plant.materials, 2.0f, options);
    EXPECT_LT(brightness(image, shadowed) * 2, brightness(image, beside));
    EXPECT_NE(brightness(image, sphereTop), brightness(image, beside)); // the sphere, not the ground
    options.shadows = false;
    const RenderedImage unshadowed = renderImage(traceOf(tracer), plant.materials, 2.0f, options);
    EXPECT_EQ(brightness(unshadowed, shadowed), brightness(unshadowed, beside));
    EXPECT_EQ(unshadowed.shadowRays, 0u);
}

// Seen from straight above, the sphere is a disc in the middle of the ground.
TEST(RenderImage, LookingStraightDownShowsTheSphereOnTheGround) {
    PlantAsset plant;
    plant.materials = defaultPalette();
    plant.primitives.push_back({Frame{glm::vec3(0, 1, 0)}, PrimitiveKind::Sphere, 3, -1, 0, 0.0f, 0.5f, 0.5f});
    const FlatTracer tracer = buildFlatTracer(plant);
    RenderOptions options;
    options.width = 64;
    options.height = 48;
    options.camera = {{0, 8, 0}, {0, 0, 0}};
    options.light = defaultLight();
    options.groundHeight = 0.0f;
    const RenderedImage image = renderImage(traceOf(tracer), plant.materials, 2.0f, options);
    EXPECT_NE(brightness(image, {32, 24}), brightness(image, {4, 4})) << "the sphere, not the ground";
    EXPECT_EQ(brightness(image, {4, 4}), brightness(image, {60, 44})) << "the ground in both corners";
}

// The graph and its flattened plant hold the same primitives a few ulps
// apart (docs/RAYTRACING.md, "Traversal"): normals rotated back level by
// level differ in their last bits, which moves a colour by one level now and
// then, and a ray grazing an edge may hit in one and miss in the other.
TEST(RenderImage, TheGraphAndItsFlattenedPlantGiveTheSamePicture) {
    for (const char* file : {"plants/fractal_bush.lsys", "plants/broadleaf.lsys", "plants/monopodial_tree.lsys"}) {
        const InstanceGraph graph = graphOf(loadOk(file));
        const PlantAsset flat = flatten(graph);
        const GraphTracer graphTracer = buildGraphTracer(graph);
        const FlatTracer flatTracer = buildFlatTracer(flat);
        const Bounds& bounds = graph.objects[graph.root].bounds;
        RenderOptions options = smallImage(bounds, 160, 120);
        options.threads = 2;
        const float size = glm::length(bounds.max - bounds.min);
        const RenderedImage throughGraph = renderImage(traceOf(graphTracer), materialsOf(graph), size, options);
        const RenderedImage throughFlat = renderImage(traceOf(flatTracer), flat.materials, size, options);
        size_t differing = 0, apart = 0;
        for (size_t i = 0; i < throughGraph.rgba.size(); i += 4) {
            int largest = 0;
            for (size_t c = 0; c < 3; ++c)
                largest = std::max(largest, std::abs(int(throughGraph.rgba[i + c]) - int(throughFlat.rgba[i + c])));
            differing += largest > 0;
            apart += largest > 2;
        }
        const size_t pixels = size_t(options.width) * options.height;
        EXPECT_LE(differing, pixels / 500) << file; // 0.2 % (6 of 19 200 for the bush)
        EXPECT_LE(apart, pixels / 5000) << file;    // 0.02 % (none)
        EXPECT_EQ(throughGraph.cameraRays, throughFlat.cameraRays);
    }
}

void expectSameMaterials(const std::vector<Material>& actual, const std::vector<Material>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < actual.size(); ++i) {
        EXPECT_EQ(actual[i].name, expected[i].name) << "material " << i;
        EXPECT_EQ(actual[i].albedo, expected[i].albedo) << "material " << i;
        EXPECT_EQ(actual[i].twoSided, expected[i].twoSided) << "material " << i;
    }
}

TEST(MaterialsOf, TheGraphsTableIsTheFlattenedPlants) {
    // Surfaces, the default palette; a vlab object's colour map.
    for (const char* file :
         {"plants/broadleaf.lsys", "plants/fractal_bush.lsys", "plants/abop/fig1_24d_bracketed_plant"}) {
        SCOPED_TRACE(file);
        const InstanceGraph graph = graphOf(loadOk(file));
        expectSameMaterials(materialsOf(graph), flatten(graph).materials);
    }
    // A polygon of material 12 (the palette repeated: "fruit 12", one-sided until a polygon uses it).
    SCOPED_TRACE("polygon");
    const InstanceGraph graph = graphOf(parseOk("Axiom: A\nA --> F;(12){.-f.+f.+f.}\n"), 1);
    ASSERT_EQ(materialsOf(graph).size(), 13u);
    EXPECT_TRUE(materialsOf(graph)[12].twoSided);
    expectSameMaterials(materialsOf(graph), flatten(graph).materials);
}

// The lazy graph's table, from its objects expanded one by one, is the whole
// graph's: the same plants, and a polygon's material made two-sided.
TEST(MaterialsOf, TheLazyGraphsTableIsTheWholeGraphs) {
    const auto expectLazyTableIsWhole = [](const Grammar& grammar, std::optional<int> steps) {
        const BGrammar bgrammar = interpretedBGrammar(grammar, steps);
        expectSameMaterials(materialsOf(deriveLazyInstanceGraph(bgrammar, grammar)),
                            materialsOf(buildInstanceGraph(bgrammar, grammar)));
    };
    for (const char* file :
         {"plants/broadleaf.lsys", "plants/fractal_bush.lsys", "plants/abop/fig1_24d_bracketed_plant"}) {
        SCOPED_TRACE(file);
        expectLazyTableIsWhole(loadOk(file), std::nullopt);
    }
    SCOPED_TRACE("polygon");
    expectLazyTableIsWhole(parseOk("Axiom: A\nA --> F;(12){.-f.+f.+f.}\n"), 1);
}

} // namespace
} // namespace lsys::test
