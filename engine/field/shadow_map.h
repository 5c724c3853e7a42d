// The sun's shadow map: one orthographic depth map over the part of the
// field near the camera, drawn in the frame's shadow pass (after the cull
// pass) from the same indirect lists as the colour pass, and sampled with
// hardware depth comparison.
#pragma once

#include "engine/vk/resources.h"

#include <glm/glm.hpp>

namespace pf {

constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;

struct ShadowMap {
    Image depth;
    VkSampler sampler = VK_NULL_HANDLE; // compare LESS_OR_EQUAL, linear (2×2 PCF per tap), white border
    uint32_t size = 0;
};

// The image and sampler are owned by `owner`.
ShadowMap createShadowMap(GpuResources& owner, uint32_t size);

// An orthographic view along the sun over a square of half-size `radius`
// around `focus`, `depthRadius` metres deep either side of it. Its origin is
// snapped to whole texels so the shadows of still plants do not crawl while
// the camera moves.
glm::mat4 sunViewProjection(const glm::vec3& sunDirection, const glm::vec3& focus, float radius, float depthRadius,
                            uint32_t mapSize);

// Begins depth-only rendering into the map (cleared to 1) with an ordinary
// (positive-height) viewport, after the previous frame's reads of it.
void beginShadowPass(VkCommandBuffer cmd, const ShadowMap& map);
// Ends it and makes the depth readable by the fragment shaders that follow.
void endShadowPass(VkCommandBuffer cmd, const ShadowMap& map);

} // namespace pf
