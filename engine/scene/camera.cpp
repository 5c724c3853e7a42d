#include "engine/scene/camera.h"

#include "lsystem/common/view_up.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace pf {

namespace {

// Up to this many near planes away the scene's own depth range still
// resolves a metre at the field (two float steps of depth at 1 km from a
// 0.1 m near plane), and ordinary cameras keep their planes.
constexpr float kNearPlanesResolved = 1e4f;
// Past that, the near plane at this share of the distance to the box: a
// metre there still spans a few float steps of depth from 10^6 m.
constexpr float kNearShare = 0.5f;

} // namespace

Camera withDepthRangeFor(const Camera& camera, const SceneBox& box) {
    const glm::vec3 outside = glm::max(box.min - camera.position, camera.position - box.max);
    const float nearest = glm::length(glm::max(outside, glm::vec3(0.0f)));
    if (!(nearest > kNearPlanesResolved * camera.nearPlane)) return camera;
    const glm::vec3 farthest = glm::max(glm::abs(box.min - camera.position), glm::abs(box.max - camera.position));
    Camera fitted = camera;
    fitted.nearPlane = kNearShare * nearest;
    fitted.farPlane = std::max(camera.farPlane, glm::length(farthest));
    return fitted;
}

glm::vec3 sunDirection(const Environment& env) {
    const float elevation = glm::radians(env.sunElevationDegrees);
    const float azimuth = glm::radians(env.sunAzimuthDegrees);
    return glm::normalize(glm::vec3(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                    -std::cos(azimuth) * std::cos(elevation)));
}

glm::mat4 viewMatrix(const Camera& camera) {
    return glm::lookAtRH(camera.position, camera.target,
                         lsys::viewUp(camera.target - camera.position, glm::vec3(0, 1, 0)));
}

glm::mat4 projectionMatrix(const Camera& camera, glm::uvec2 viewport) {
    const float aspect = float(viewport.x) / float(viewport.y);
    return glm::perspectiveRH_ZO(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane, camera.farPlane);
}

gpu::FrameUniforms makeFrameUniforms(const Camera& camera, const Environment& env, glm::uvec2 viewport, float time) {
    gpu::FrameUniforms u{};
    u.viewProj = projectionMatrix(camera, viewport) * viewMatrix(camera);
    u.invViewProj = glm::inverse(u.viewProj);
    u.cameraPosition = glm::vec4(camera.position, time);
    u.sunDirection = glm::vec4(sunDirection(env), 0.0f);
    u.sunRadiance = glm::vec4(env.sunRadiance, 0.0f);
    u.skyZenith = glm::vec4(env.skyZenith, 0.0f);
    u.skyHorizon = glm::vec4(env.skyHorizon, 0.0f);
    u.groundAlbedo = glm::vec4(env.groundAlbedo, 0.0f);
    u.fog = glm::vec4(env.fogDensity, env.groundHalfSize, 0.0f, 0.0f);
    return u;
}

} // namespace pf
