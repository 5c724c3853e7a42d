// The ray tracer's image of a plant (lsystem/raytrace/render.h, as lsys
// render makes it) against the rasteriser's (engine/field, as plantfield
// draws a field): the plant placed in a field with a position, yaw and scale,
// lsys render's framed camera carried from plant space into the world, and
// the pixels each covers compared. Validation is on (GpuTest).

#include "../instance_graph/instance_graph_test_support.h"
#include "engine/field/field_renderer.h"
#include "engine/image/image.h"
#include "engine/scene/field_content.h"
#include "engine/vk/capture.h"
#include "gpu_test.h"
#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/raytrace/render.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pf::test {
namespace {

constexpr VkExtent2D kSize{160, 120};
constexpr const char* kPlantFile = "plants/broadleaf.lsys";

// A pixel belongs to the plant where it differs from the same view without
// the plant by more than this in some channel (of 255): both renderers draw
// the background the same in both images, bit for bit.
constexpr int kBackgroundDelta = 0;

// One tree standing in a flat field off the origin, turned and scaled: the
// placement the ray tracer's camera must be carried through. No wind (the
// tree at rest), no fog, full detail at any size; grown from `seed`, the
// file's, as lsys render grows it.
Scene oneTreeScene(uint32_t seed) {
    Scene scene;
    scene.terrain.size = 200.0f;
    scene.terrain.resolution = 65;
    NoiseHeightfield flat;
    flat.amplitude = 0.0f;
    flat.octaves = 1;
    scene.terrain.heightfield = flat;
    scene.wind.speed = 0.0f;
    scene.wind.gustStrength = 0.0f;
    scene.wind.turbulence = 0.0f;
    scene.fog.density = 0.0f;
    Species tree;
    tree.name = "tree";
    tree.lsystem = std::string(PLANTFIELD_DATA_DIR) + "/" + kPlantFile;
    tree.seed = seed;
    tree.height = 6.0f;
    tree.lod.reducedBelowPixels = 0.0f;
    tree.lod.impostorBelowPixels = 0.0f;
    tree.placement.mode = PlacementMode::Explicit;
    tree.placement.instances = {PlacedPlant{{7.0f, -4.0f}, 35.0f, 1.25f}};
    scene.species.push_back(std::move(tree));
    return scene;
}

// Plant space into the world as the field's vertex shader places a plant
// (plantToWorld in shaders/field_common.glsl): scaled by the species height's
// scale and the instance's, turned by its yaw about +y, moved to its position.
struct PlantPlacement {
    glm::vec3 position{0.0f};
    float yaw = 0.0f; // radians
    float scale = 1.0f;
};

PlantPlacement placementOf(const FieldContent& content) {
    const PlantInstance& plant = content.plants.at(0);
    return {plant.position, plant.rotation, plant.scale * content.models.assets.at(0).scale};
}

glm::vec3 toWorld(const PlantPlacement& placement, glm::vec3 point) {
    return placement.position + glm::angleAxis(placement.yaw, glm::vec3(0.0f, 1.0f, 0.0f)) * (placement.scale * point);
}

// lsys render's camera seen in the world: the yaw leaves +y up, and a
// uniform scale keeps the field of view.
Camera worldCamera(const lsys::PinholeCamera& camera, const PlantPlacement& placement) {
    Camera world;
    world.position = toWorld(placement, camera.position);
    world.target = toWorld(placement, camera.target);
    world.fovYDegrees = camera.fovYDegrees;
    const float distance = glm::distance(world.position, world.target);
    world.nearPlane = 0.01f * distance;
    world.farPlane = 100.0f * distance;
    return world;
}

// One frame of a fresh renderer: no shadows (a shadow on the ground is not
// the plant), no anti-aliasing (a pixel is the plant's where its centre is,
// as a ray through the centre decides).
RgbaImage rasterised(const GpuContext& ctx, const FieldContent& content, const Camera& camera) {
    FieldRenderSettings settings;
    settings.shadows = SunShadows::none;
    settings.antialiasing.method = AntialiasMethod::none;
    settings.clusters.enabled = false; // the one plant through the per-plant cull, wherever it is moved
    FieldRenderer renderer(ctx, content, settings);
    RenderTarget target = createRenderTarget(ctx, kSize, renderer.antialiasing());
    FieldView view;
    view.camera = camera;
    renderer.setView(view, kSize);
    RgbaImage image =
        captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t); });
    destroyRenderTarget(target);
    return image;
}

// The image lsys render traces (without shadows, as rasterised), lit by the
// scene's sun and sky.
lsys::RenderedImage traced(const lsys::PlantTrace& trace, const std::vector<lsys::Material>& materials, float sceneSize,
                           const lsys::PinholeCamera& camera, const Environment& environment) {
    lsys::RenderOptions options;
    options.width = kSize.width;
    options.height = kSize.height;
    options.camera = camera;
    options.light = {sunDirection(environment), environment.sunRadiance, environment.skyZenith, environment.skyHorizon,
                     environment.groundAlbedo};
    options.shadows = false;
    options.groundHeight = 0.0f;
    options.threads = 2;
    return lsys::renderImage(trace, materials, sceneSize, options);
}

// The pixels where `image` differs from `background`.
std::vector<bool> coverage(const std::vector<uint8_t>& image, const std::vector<uint8_t>& background) {
    std::vector<bool> covered(image.size() / 4);
    for (size_t p = 0; p < covered.size(); ++p)
        for (size_t c = 0; c < 3; ++c)
            if (std::abs(int(image[p * 4 + c]) - int(background[p * 4 + c])) > kBackgroundDelta) covered[p] = true;
    return covered;
}

struct Agreement {
    size_t both = 0, tracedOnly = 0, rasterisedOnly = 0, pixels = 0;
    double intersectionOverUnion() const { return double(both) / double(both + tracedOnly + rasterisedOnly); }
    double mismatchShare() const { return double(tracedOnly + rasterisedOnly) / double(pixels); }
};

Agreement agreementOf(const std::vector<bool>& traced, const std::vector<bool>& rasterised) {
    Agreement agreement;
    agreement.pixels = traced.size();
    for (size_t p = 0; p < traced.size(); ++p) {
        agreement.both += traced[p] && rasterised[p];
        agreement.tracedOnly += traced[p] && !rasterised[p];
        agreement.rasterisedOnly += !traced[p] && rasterised[p];
    }
    return agreement;
}

// White where both cover a pixel, red where only the tracer does, blue where
// only the rasteriser does, black where neither.
RgbaImage maskDifference(const std::vector<bool>& traced, const std::vector<bool>& rasterised) {
    RgbaImage image{kSize.width, kSize.height, std::vector<uint8_t>(traced.size() * 4, 255)};
    for (size_t p = 0; p < traced.size(); ++p) {
        image.pixels[p * 4 + 0] = traced[p] ? 255 : 0;
        image.pixels[p * 4 + 1] = traced[p] && rasterised[p] ? 255 : 0;
        image.pixels[p * 4 + 2] = rasterised[p] ? 255 : 0;
    }
    return image;
}

constexpr double kMinIntersectionOverUnion = 0.9; // measured and argued at the test below

class RasterSilhouetteTest : public GpuTest {};

// The broadleaf tree (bark and ~leaf surfaces) covers the same pixels in
// both but where the drawn form is not the traced primitives (docs/
// RAYTRACING.md, "Not matched": leaf cards cut by the leaf's outline against
// its 56 triangles, bark as generalised cylinders of 8 sides or fewer
// against exact cone frusta) and where a twig or leaf edge a pixel wide falls
// either side of a pixel's centre. Measured on lavapipe: 1 810 pixels traced,
// 1 736 rasterised, 1 706 in both, so an intersection over union of 0.927
// (0.70 % of the image mismatching). The bound, kMinIntersectionOverUnion,
// is 0.9: 0.027 below that, and above what a camera carried through the placement a little wrongly gives
// (the yaw off by 1°: 0.865, by 2°: 0.81 to 0.82; the scale off by 2 or 3 %,
// or the plant 0.1 m (1.7 % of its height) to either side: 0.69 to 0.73).
TEST_F(RasterSilhouetteTest, TracedAndRasterisedTreeCoverTheSamePixels) {
    const lsys::Grammar grammar = lsys::test::loadOk(kPlantFile);
    const FieldContent content = buildFieldContent(oneTreeScene(uint32_t(grammar.seed)), std::nullopt, {},
                                                   lsys::machineMemoryBudget(), ModelAssets::Keep);
    const PlantPlacement placement = placementOf(content);

    // The traced plant and lsys render's camera framed on it, in plant space.
    const lsys::InstanceGraph graph = lsys::test::graphOf(grammar);
    const lsys::GraphTracer tracer = lsys::buildGraphTracer(graph);
    const lsys::Bounds bounds = tracer.objectBounds[graph.root];
    const lsys::PinholeCamera camera = lsys::framedCamera(bounds, float(kSize.width) / float(kSize.height));
    const float sceneSize = glm::length(bounds.max - bounds.min);
    const std::vector<lsys::Material> materials = lsys::materialsOf(graph);
    const lsys::RenderedImage tracedPlant =
        traced(lsys::traceOf(tracer), materials, sceneSize, camera, environmentOf(content.scene));
    const lsys::RenderedImage tracedBackground =
        traced([](const lsys::Ray&, lsys::HitQuery) { return std::optional<lsys::Hit>(); }, materials, sceneSize,
               camera, environmentOf(content.scene));

    // The rasterised field from that camera: the tree where it stands, and
    // again moved behind the camera for the background.
    const Camera view = worldCamera(camera, placement);
    const RgbaImage rasterisedPlant = rasterised(ctx, content, view);
    FieldContent withoutPlant = content;
    withoutPlant.plants[0].position = view.position + 2.0f * (view.position - view.target);
    const RgbaImage rasterisedBackground = rasterised(ctx, withoutPlant, view);

    const std::vector<bool> tracedMask = coverage(tracedPlant.rgba, tracedBackground.rgba);
    const std::vector<bool> rasterisedMask = coverage(rasterisedPlant.pixels, rasterisedBackground.pixels);
    const Agreement agreement = agreementOf(tracedMask, rasterisedMask);
    const std::string report = "traced " + std::to_string(agreement.both + agreement.tracedOnly) +
                               " pixels, rasterised " + std::to_string(agreement.both + agreement.rasterisedOnly) +
                               ", both " + std::to_string(agreement.both) + ": IoU " +
                               std::to_string(agreement.intersectionOverUnion()) + ", " +
                               std::to_string(100.0 * agreement.mismatchShare()) + " % of the pixels mismatching";
    std::printf("%s\n", report.c_str());
    // The plant fills a good part of the frame in both (a camera that missed it would agree on the background).
    EXPECT_GT(agreement.both, agreement.pixels / 20) << report;
    EXPECT_GE(agreement.intersectionOverUnion(), kMinIntersectionOverUnion) << report;
    if (HasFailure()) {
        const std::string dir = PLANTFIELD_TEST_OUTPUT_DIR;
        std::filesystem::create_directories(dir);
        writePng(dir + "/tree-traced.png", {tracedPlant.width, tracedPlant.height, tracedPlant.rgba});
        writePng(dir + "/tree-rasterised.png", rasterisedPlant);
        writePng(dir + "/tree-coverage-diff.png", maskDifference(tracedMask, rasterisedMask));
        ADD_FAILURE() << "wrote " << dir << "/tree-traced.png, tree-rasterised.png and tree-coverage-diff.png";
    }
}

} // namespace
} // namespace pf::test
