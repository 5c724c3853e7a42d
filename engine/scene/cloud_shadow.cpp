#include "engine/scene/cloud_shadow.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// The extinction per radius of path of shaders/cloud.frag.
constexpr float kCloudExtinction = 1.2f;

} // namespace

glm::vec2 cloudShadowPlanePoint(const glm::vec3& point, const glm::vec3& sun) {
    return glm::vec2(point.x, point.z) - glm::vec2(sun.x, sun.z) * (point.y / sun.y);
}

CloudShadowMap bakeCloudShadows(const std::vector<Cloud>& clouds, const glm::vec3& sun, float texelMetres) {
    CloudShadowMap map;
    if (sun.y <= std::sin(glm::radians(3.0f))) return map;
    // A sphere's shadow on the plane lies within its radius / sun.y of its centre's point.
    glm::vec2 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    std::vector<const CloudSphere*> casters;
    for (const Cloud& cloud : clouds) {
        if (!cloud.shadow) continue;
        for (const CloudSphere& sphere : cloud.spheres) {
            const glm::vec2 centre = cloudShadowPlanePoint(sphere.centre, sun);
            low = glm::min(low, centre - sphere.radius / sun.y);
            high = glm::max(high, centre + sphere.radius / sun.y);
            casters.push_back(&sphere);
        }
    }
    if (casters.empty()) return map;
    const glm::vec2 extent = high - low;
    map.texel = std::max(texelMetres, std::max(extent.x, extent.y) / float(kCloudShadowMaxSide - 4));
    map.origin = low - 2.0f * map.texel;
    map.width = uint32_t(std::ceil(extent.x / map.texel)) + 5;
    map.height = uint32_t(std::ceil(extent.y / map.texel)) + 5;
    std::vector<float> depth(size_t(map.width) * map.height, 0.0f);
    for (const CloudSphere* sphere : casters) {
        const glm::vec2 centre = cloudShadowPlanePoint(sphere->centre, sun);
        const float reach = sphere->radius / sun.y;
        const glm::ivec2 first = glm::max(glm::ivec2(glm::ceil((centre - reach - map.origin) / map.texel)), 0);
        const glm::ivec2 last = glm::min(glm::ivec2(glm::floor((centre + reach - map.origin) / map.texel)),
                                         glm::ivec2(map.width - 1, map.height - 1));
        for (int z = first.y; z <= last.y; ++z)
            for (int x = first.x; x <= last.x; ++x) {
                const glm::vec2 at = map.origin + glm::vec2(x, z) * map.texel;
                const glm::vec3 toCentre = sphere->centre - glm::vec3(at.x, 0.0f, at.y);
                const float along = glm::dot(toCentre, sun);
                const float miss = glm::dot(toCentre, toCentre) - along * along;
                const float r2 = sphere->radius * sphere->radius;
                if (miss < r2) depth[size_t(z) * map.width + x] += 2.0f * std::sqrt(r2 - miss) / sphere->radius;
            }
    }
    map.transmittance.resize(depth.size());
    for (size_t i = 0; i < depth.size(); ++i) map.transmittance[i] = std::exp(-kCloudExtinction * depth[i]);
    return map;
}

} // namespace pf
