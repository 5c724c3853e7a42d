#include "engine/scene/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pf {

glm::vec3 sunDirection(const Environment& env) {
    const float elevation = glm::radians(env.sunElevationDegrees);
    const float azimuth = glm::radians(env.sunAzimuthDegrees);
    return glm::normalize(glm::vec3(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                    -std::cos(azimuth) * std::cos(elevation)));
}

glm::mat4 viewMatrix(const Camera& camera) { return glm::lookAtRH(camera.position, camera.target, glm::vec3(0, 1, 0)); }

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
