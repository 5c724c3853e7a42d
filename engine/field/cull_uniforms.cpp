#include "engine/field/cull_uniforms.h"

#include "engine/image/depth_pyramid_levels.h"

#include <algorithm>
#include <cmath>

namespace pf {

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj) {
    // Gribb–Hartmann: clip-space tests −w ≤ x,y ≤ w and 0 ≤ z ≤ w are planes
    // in world space made of the matrix rows (glm is column-major: m[c][r]).
    auto row = [&](int r) { return glm::vec4(viewProj[0][r], viewProj[1][r], viewProj[2][r], viewProj[3][r]); };
    std::array<glm::vec4, 6> planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                       row(3) - row(1), row(2),          row(3) - row(2)};
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

float pixelsPerMetre(float fovYRadians, uint32_t viewportHeight) {
    return float(viewportHeight) / (2.0f * std::tan(fovYRadians * 0.5f));
}

gpu::CullUniforms makeCullUniforms(const glm::mat4& viewProj, const glm::vec3& cameraPosition, float fovYRadians,
                                   uint32_t viewportHeight, float deltaSeconds, bool firstFrame, uint32_t forcedLod) {
    gpu::CullUniforms u{};
    const std::array<glm::vec4, 6> planes = frustumPlanes(viewProj);
    std::copy(planes.begin(), planes.end(), u.frustum);
    u.camera = glm::vec4(cameraPosition, pixelsPerMetre(fovYRadians, viewportHeight));
    u.counts = glm::uvec4(0, 0, forcedLod, firstFrame ? 1u : 0u);
    u.timing = glm::vec4(deltaSeconds, 0, 0, 0);
    return u;
}

void setOcclusionUniforms(gpu::CullUniforms& u, const glm::mat4& view, const glm::mat4& projection, glm::uvec2 viewport,
                          float nearPlane, uint32_t pyramidLevels) {
    u.view = view;
    u.projection = glm::vec4(projection[0][0], projection[1][1], projection[2][2], projection[3][2]);
    u.viewport = glm::vec4(float(viewport.x), float(viewport.y), nearPlane, float(pyramidLevels));
}

gpu::CullUniforms cameraCullUniforms(const glm::mat4& viewProj, const Camera& camera, glm::uvec2 viewport,
                                     float deltaSeconds, bool firstFrame, uint32_t forcedLod) {
    gpu::CullUniforms u = makeCullUniforms(viewProj, camera.position, glm::radians(camera.fovYDegrees), viewport.y,
                                           deltaSeconds, firstFrame, forcedLod);
    setOcclusionUniforms(u, viewMatrix(camera), projectionMatrix(camera, viewport), viewport, camera.nearPlane,
                         uint32_t(depthPyramidExtents({viewport.x, viewport.y}).size()));
    return u;
}

} // namespace pf
