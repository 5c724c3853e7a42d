#include "engine/field/shadow_cache.h"

#include "engine/field/cull_uniforms.h"

#include <cmath>

namespace pf {

ShadowView shadowViewAhead(const Camera& camera, const glm::vec3& sunDirection, float radius, uint32_t texels,
                           uint32_t viewportHeight, uint32_t forcedLod) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 flatForward = glm::length(glm::vec2(forward.x, forward.z)) > 1e-3f
                                      ? glm::normalize(glm::vec3(forward.x, 0.0f, forward.z))
                                      : glm::vec3(0.0f);
    const glm::vec3 focus = camera.position + flatForward * (0.6f * radius);
    ShadowView frame;
    frame.square = sunSquareAround(sunDirection, focus, radius, texels);
    frame.sunDirection = sunDirection;
    frame.camera = camera.position;
    frame.pixelsPerMetre = pixelsPerMetre(glm::radians(camera.fovYDegrees), viewportHeight);
    frame.forcedLod = forcedLod;
    return frame;
}

uint32_t shadowCacheMargin(const ShadowCacheSettings& settings, float texel) {
    return uint32_t(std::ceil(settings.reach / texel));
}

ShadowView shadowCacheFor(const ShadowView& frame, uint32_t margin) {
    ShadowView cache = frame;
    cache.square = grownSquare(frame.square, margin);
    return cache;
}

bool shadowCacheServes(const ShadowView& cache, const ShadowView& frame, const ShadowCacheSettings& settings) {
    const float fewest = cache.pixelsPerMetre * (1.0f - settings.pixelTolerance);
    const float most = cache.pixelsPerMetre * (1.0f + settings.pixelTolerance);
    return cache.sunDirection == frame.sunDirection && cache.forcedLod == frame.forcedLod &&
           cache.square.texel == frame.square.texel && glm::distance(cache.camera, frame.camera) <= settings.reach &&
           frame.pixelsPerMetre >= fewest && frame.pixelsPerMetre <= most &&
           squareContains(cache.square, frame.square) &&
           std::abs(frame.square.depth - cache.square.depth) <= settings.reach;
}

} // namespace pf
