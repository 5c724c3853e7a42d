// The sun's shadow map: one orthographic depth map over the part of the
// field near the camera, sampled with hardware depth comparison. Each frame
// it starts as its window of the cache — a larger map of the static casters
// on the same texel grid, drawn only when the frame moves out of it
// (shadow_cache.h) — and the frame's own casters are drawn on top of it
// (shadow_casters.h).
#pragma once

#include "engine/field/sun_square.h"
#include "engine/vk/resources.h"

namespace pf {

constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;

struct ShadowMap {
    Image depth;                        // the frame's map, size² texels, sampled by the colour pass
    Image cache;                        // the static casters, cacheSize² texels, copied from
    VkSampler sampler = VK_NULL_HANDLE; // compare LESS_OR_EQUAL, linear (2×2 PCF per tap), white border
    uint32_t size = 0;
    uint32_t cacheSize = 0;
};

// The images and sampler are owned by `owner`; the cache is `cacheMargin`
// texels wider than the map on every side.
ShadowMap createShadowMap(GpuResources& owner, uint32_t size, uint32_t cacheMargin);

// Depth-only rendering starts with an ordinary (positive-height) viewport:
// into the frame's map cleared to 1, after the previous frame's reads of it;
void beginShadowPass(VkCommandBuffer cmd, const ShadowMap& map);
// into the cache cleared to 1, after the copies out of it;
void beginShadowCachePass(VkCommandBuffer cmd, const ShadowMap& map);
// or into the frame's map after copying into it the cache's window that
// starts `offset` texels into the cache.
void beginShadowPassFromCache(VkCommandBuffer cmd, const ShadowMap& map, glm::ivec2 offset);
// Ends the cache's pass and makes it the source of the copies.
void endShadowCachePass(VkCommandBuffer cmd, const ShadowMap& map);
// Ends the frame's pass and makes its depth readable by the fragment shaders that follow.
void endShadowPass(VkCommandBuffer cmd, const ShadowMap& map);

} // namespace pf
