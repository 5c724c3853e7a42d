#include "lsystem/raytrace/render.h"

#include "lsystem/common/view_up.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace lsys {
namespace {

// The plant shaders' constants (shaders/plant.frag, shaders/plant_surface.glsl):
// how much sky a surface inside the crown sees, and the share of the sun that
// thin foliage lets through to its back face.
constexpr float kFoliageOcclusion = 0.75f;
constexpr float kBarkOcclusion = 0.85f;
constexpr float kFoliageTransmission = 0.35f;
// How far a shadow ray starts off the surface, as a fraction of the plant's
// extent: past the float rounding of a hit point on the plant, well inside
// the thinnest twig's radius.
constexpr float kShadowOffset = 1e-4f;

// The camera's orthonormal frame and the image plane's half extents at unit distance.
struct CameraBasis {
    glm::vec3 position, forward, right, up;
    float halfWidth, halfHeight;
};

CameraBasis basisOf(const PinholeCamera& camera, float aspect) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, viewUp(camera.target - camera.position, camera.up)));
    const float halfHeight = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    return {camera.position, forward, right, glm::cross(right, forward), halfHeight * aspect, halfHeight};
}

Ray rayThrough(const CameraBasis& basis, uint32_t width, uint32_t height, float x, float y) {
    const float sx = (2.0f * x / float(width) - 1.0f) * basis.halfWidth;
    const float sy = (1.0f - 2.0f * y / float(height)) * basis.halfHeight;
    return {basis.position, glm::normalize(basis.forward + sx * basis.right + sy * basis.up)};
}

// The sky seen along a unit direction: shaders/common.glsl's skyRadiance.
glm::vec3 skyRadiance(const Lighting& light, const glm::vec3& direction) {
    const float up = std::clamp(direction.y, 0.0f, 1.0f);
    glm::vec3 sky = glm::mix(light.skyHorizon, light.skyZenith, std::sqrt(up));
    if (direction.y < 0.0f) // below the horizon the dome fades to a darker ground bounce
        sky = glm::mix(light.skyHorizon, light.groundAlbedo * 0.5f, std::clamp(-direction.y * 4.0f, 0.0f, 1.0f));
    const float sunDot = std::max(glm::dot(direction, light.sunDirection), 0.0f);
    const float sun8 = std::pow(sunDot, 8.0f), sun64 = std::pow(sunDot, 64.0f);
    const float disc = glm::smoothstep(0.9995f, 0.9998f, sunDot) * 8.0f;
    return sky + light.sunRadiance * (0.02f * sun8 + 0.25f * sun64 + disc);
}

// A surface lit by the sun (its `visibility` from the shadow ray) and the sky:
// shaders/field_common.glsl's shadeFieldSeen.
glm::vec3 shadeSeen(const Lighting& light, const glm::vec3& albedo, const glm::vec3& normal, float visibility,
                    float occlusion, float transmission) {
    const float facing = glm::dot(normal, light.sunDirection);
    const float sun = std::max(facing, 0.0f) + transmission * std::max(-facing, 0.0f);
    const float skyWeight = 0.5f + 0.5f * normal.y;
    const glm::vec3 ambient = glm::mix(light.groundAlbedo * light.skyHorizon, light.skyZenith, skyWeight);
    return albedo * (light.sunRadiance * sun * visibility + ambient * occlusion);
}

// Narkowicz's fit of the ACES filmic curve (shaders/common.glsl's toneMap).
glm::vec3 toneMap(const glm::vec3& x) {
    return glm::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

uint8_t srgbByte(float linear) {
    const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(std::clamp(encoded, 0.0f, 1.0f) * 255.0f));
}

// What one pixel's rays need: the plant, its colours, the light.
struct Scene {
    const PlantTrace& trace;
    const std::vector<Material>& materials;
    const RenderOptions& options;
    float shadowOffset;
};

struct RayCounts {
    uint64_t camera = 0, shadow = 0;
};

// 1 when nothing lies between `point` (moved off its surface along `normal`,
// turned to the sun's side) and the sun, else 0.
float sunVisibility(const Scene& scene, const glm::vec3& point, const glm::vec3& normal, RayCounts& counts) {
    if (!scene.options.shadows) return 1.0f;
    const glm::vec3 sun = scene.options.light.sunDirection;
    const glm::vec3 sunward = glm::dot(normal, sun) >= 0.0f ? normal : -normal;
    ++counts.shadow;
    const Ray ray{point + sunward * scene.shadowOffset, sun};
    return scene.trace(ray, HitQuery::Any) ? 0.0f : 1.0f;
}

// The linear radiance seen along a camera ray.
glm::vec3 radiance(const Scene& scene, Ray ray, RayCounts& counts) {
    const Lighting& light = scene.options.light;
    std::optional<float> groundT;
    if (scene.options.groundHeight && ray.direction.y < 0.0f) {
        groundT = (*scene.options.groundHeight - ray.origin.y) / ray.direction.y;
        if (*groundT >= 0.0f)
            ray.tMax = *groundT;
        else
            groundT.reset();
    }
    ++counts.camera;
    if (const std::optional<Hit> hit = scene.trace(ray, HitQuery::Closest)) {
        const Material& material = scene.materials.at(hit->material);
        const bool foliage =
            material.twoSided || hit->kind == PrimitiveKind::Surface || hit->kind == PrimitiveKind::Polygon;
        // The side the camera sees: leaves are two-sided, and a closed shape is seen from outside.
        const glm::vec3 normal = glm::dot(hit->normal, ray.direction) > 0.0f ? -hit->normal : hit->normal;
        const glm::vec3 point = ray.origin + hit->t * ray.direction;
        const float facing = glm::dot(normal, light.sunDirection);
        const float transmission = foliage ? kFoliageTransmission : 0.0f;
        const bool sunlit = facing > 0.0f || transmission > 0.0f;
        const float visibility = sunlit ? sunVisibility(scene, point, normal, counts) : 0.0f;
        return shadeSeen(light, material.albedo, normal, visibility, foliage ? kFoliageOcclusion : kBarkOcclusion,
                         transmission);
    }
    if (groundT) {
        const glm::vec3 up{0.0f, 1.0f, 0.0f};
        const glm::vec3 point = ray.origin + *groundT * ray.direction;
        const float visibility = light.sunDirection.y > 0.0f ? sunVisibility(scene, point, up, counts) : 0.0f;
        return shadeSeen(light, light.groundAlbedo, up, visibility, 1.0f, 0.0f);
    }
    return skyRadiance(light, ray.direction);
}

// Where in a pixel its samples lie: the R2 sequence (Roberts 2018, "The
// unreasonable effectiveness of quasirandom sequences"), the first at its centre.
std::vector<glm::vec2> sampleOffsets(uint32_t samples) {
    constexpr double g = 1.32471795724474602596; // the plastic number
    std::vector<glm::vec2> offsets;
    for (uint32_t k = 0; k < samples; ++k) {
        const double x = 0.5 + k / g, y = 0.5 + k / (g * g);
        offsets.emplace_back(float(x - std::floor(x)), float(y - std::floor(y)));
    }
    return offsets;
}

void renderRow(const Scene& scene, const CameraBasis& basis, const std::vector<glm::vec2>& offsets, uint32_t row,
               RenderedImage& image, RayCounts& counts) {
    for (uint32_t column = 0; column < image.width; ++column) {
        glm::vec3 sum{0.0f};
        for (const glm::vec2& offset : offsets) {
            const Ray ray =
                rayThrough(basis, image.width, image.height, float(column) + offset.x, float(row) + offset.y);
            sum += toneMap(radiance(scene, ray, counts));
        }
        const glm::vec3 color = sum / float(offsets.size());
        uint8_t* pixel = &image.rgba[(size_t(row) * image.width + column) * 4];
        pixel[0] = srgbByte(color.r);
        pixel[1] = srgbByte(color.g);
        pixel[2] = srgbByte(color.b);
        pixel[3] = 255;
    }
}

} // namespace

PinholeCamera framedCamera(const Bounds& bounds, float aspect, ViewAngles angles, float fovYDegrees, float margin) {
    PinholeCamera camera;
    camera.fovYDegrees = fovYDegrees;
    const float azimuth = glm::radians(angles.azimuthDegrees), elevation = glm::radians(angles.elevationDegrees);
    const glm::vec3 back{std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                         -std::cos(azimuth) * std::cos(elevation)};
    camera.target = bounds.empty() ? glm::vec3(0.0f) : 0.5f * (bounds.min + bounds.max);
    const CameraBasis basis = basisOf({camera.target + back, camera.target, camera.up, fovYDegrees}, aspect);
    // A corner at c from the target lies in the image when |c·right| and
    // |c·up| are within the half extents times its depth, distance + c·forward.
    const float halfWidth = basis.halfWidth * (1.0f - margin), halfHeight = basis.halfHeight * (1.0f - margin);
    float distance = 0.0f;
    for (int corner = 0; !bounds.empty() && corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                          corner & 4 ? bounds.max.z : bounds.min.z};
        const glm::vec3 c = p - camera.target;
        const float across =
            std::max(std::abs(glm::dot(c, basis.right)) / halfWidth, std::abs(glm::dot(c, basis.up)) / halfHeight);
        distance = std::max(distance, across - glm::dot(c, basis.forward));
    }
    camera.position = camera.target + back * (distance > 0.0f ? distance : 1.0f);
    return camera;
}

Ray cameraRay(const PinholeCamera& camera, uint32_t width, uint32_t height, float x, float y) {
    return rayThrough(basisOf(camera, float(width) / float(height)), width, height, x, y);
}

RenderedImage renderImage(const PlantTrace& trace, const std::vector<Material>& materials, float sceneSize,
                          const RenderOptions& options) {
    RenderedImage image{options.width, options.height,
                        std::vector<uint8_t>(size_t(options.width) * options.height * 4)};
    const Scene scene{trace, materials, options, kShadowOffset * sceneSize};
    const CameraBasis basis = basisOf(options.camera, float(options.width) / float(options.height));
    const std::vector<glm::vec2> offsets = sampleOffsets(std::max(options.samples, 1u));

    // Rows are handed out one at a time; each pixel is computed alone, so the
    // bytes do not depend on which thread traced it.
    std::atomic<uint32_t> nextRow{0};
    std::atomic<uint64_t> cameraRays{0}, shadowRays{0};
    std::mutex reporting;
    uint32_t rowsDone = 0;
    std::exception_ptr failure;
    auto work = [&] {
        RayCounts counts;
        try {
            for (uint32_t row; (row = nextRow.fetch_add(1)) < options.height;) {
                renderRow(scene, basis, offsets, row, image, counts);
                const std::lock_guard lock(reporting);
                ++rowsDone;
                if (options.onRow) options.onRow(rowsDone);
            }
        } catch (...) { // rethrown on the calling thread; the other threads stop after their row
            const std::lock_guard lock(reporting);
            if (!failure) failure = std::current_exception();
            nextRow = options.height;
        }
        cameraRays += counts.camera;
        shadowRays += counts.shadow;
    };
    std::vector<std::thread> threads;
    for (uint32_t i = 1; i < options.threads; ++i) threads.emplace_back(work);
    work();
    for (std::thread& thread : threads) thread.join();
    if (failure) std::rethrow_exception(failure);
    image.cameraRays = cameraRays;
    image.shadowRays = shadowRays;
    return image;
}

} // namespace lsys
