#include "engine/field/shadow_cache.h"

#include <cmath>

namespace pf {

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
