// GPU layout of the depth pyramid's reduction (engine/vk/depth_pyramid.h,
// docs/CULLING.md), shared by GLSL and C++.
#ifndef PLANTFIELD_SHADERS_DEPTH_PYRAMID_LAYOUTS_H
#define PLANTFIELD_SHADERS_DEPTH_PYRAMID_LAYOUTS_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using uvec4 = glm::uvec4;
#endif

#define DEPTH_REDUCE_GROUP_SIZE 8 // 8×8 invocations, one a texel written

// The reduction's set: the level below (or the depth buffer) and the level written.
#define DEPTH_REDUCE_BINDING_SOURCE 0 // sampler2D (sampler2DMS for a multisampled depth buffer)
#define DEPTH_REDUCE_BINDING_TARGET 1 // image2D r32f: one level of the pyramid
// The set a reader samples the whole pyramid through (texelFetch of any level).
#define DEPTH_PYRAMID_BINDING 0

struct DepthReducePush {
    uvec4 size;    // xy source size, zw target size (texels)
    uvec4 samples; // x samples a pixel of a multisampled source (1 otherwise), yzw 0
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::DepthReducePush) == 32);
#endif

#endif
