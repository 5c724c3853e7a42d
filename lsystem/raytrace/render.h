#pragma once
// An image of one plant ray traced on the CPU (docs/RAYTRACING.md, "Rendering
// an image"): a pinhole camera, the sun with ray-traced shadows, the sky as
// ambient light, an optional ground plane at the plant's base. Generic over
// the tracer: anything with a trace(tracer, Ray, HitQuery) overload
// (FlatTracer, GraphTracer) is wrapped by traceOf.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/raytrace/ray.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// The nearest (Closest) or any (Any) hit of a ray with the plant, in plant space.
using PlantTrace = std::function<std::optional<Hit>(const Ray&, HitQuery)>;

// The trace function of a tracer that must outlive it.
template <typename Tracer>
PlantTrace traceOf(const Tracer& tracer) {
    return [&tracer](const Ray& ray, HitQuery query) { return trace(tracer, ray, query); };
}

// A pinhole camera: the image's vertical field of view, the horizontal one
// following from the image's aspect ratio.
struct PinholeCamera {
    glm::vec3 position{0.0f, 0.0f, 1.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
};

// The light, as the renderer's pf::Environment gives it (the lsys CLI fills
// it from there): a unit vector towards the sun, linear radiances and albedo.
struct Lighting {
    glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};
    glm::vec3 sunRadiance{0.0f};
    glm::vec3 skyZenith{0.0f};
    glm::vec3 skyHorizon{0.0f};
    glm::vec3 groundAlbedo{0.0f};
};

// Where the automatic framing looks from: degrees clockwise from -z towards
// +x (the sun's convention) and above the horizon. The default sees a plant
// drawn in the x-y plane three-quarters on, lit by the renderer's default sun
// from the right and casting its shadow behind it to the left.
struct ViewAngles {
    float azimuthDegrees = 200.0f;
    float elevationDegrees = 20.0f;
};

// A camera at `angles` looking at the box's centre, as near as it can be with
// every corner of the box in an image of `aspect` (width / height), the box
// kept `margin` (a fraction of the half-image) inside each edge.
PinholeCamera framedCamera(const Bounds& bounds, float aspect, ViewAngles angles = {}, float fovYDegrees = 45.0f,
                           float margin = 0.05f);

// The ray through image point (x, y) in pixels, (0, 0) the top-left corner of
// the top-left pixel: from the camera's position, direction of unit length.
Ray cameraRay(const PinholeCamera& camera, uint32_t width, uint32_t height, float x, float y);

struct RenderOptions {
    uint32_t width = 1280;
    uint32_t height = 720;
    PinholeCamera camera;
    Lighting light;
    bool shadows = true;
    // A ground plane at this height (plant space y), lit and shadowed as the plant is.
    std::optional<float> groundHeight;
    uint32_t samples = 1; // rays per pixel, spread over it (R2 sequence, Roberts 2018)
    uint32_t threads = 1;
    // Called after each row, with the rows done so far, from whichever thread
    // finished it (never two at once).
    std::function<void(uint32_t rowsDone)> onRow;
};

struct RenderedImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba; // row-major, top row first, sRGB, alpha 255
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
};

// Traces every pixel. `materials` colours each hit by Hit::material (a
// PlantAsset's table, or materialsOf(graph)); `sceneSize` (the plant's
// extent) sets how far shadow rays start off the surface. The bytes are the
// same whatever options.threads.
RenderedImage renderImage(const PlantTrace& trace, const std::vector<Material>& materials, float sceneSize,
                          const RenderOptions& options);

} // namespace lsys
