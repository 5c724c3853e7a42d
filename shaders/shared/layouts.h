// GPU data layouts shared by GLSL and C++. Every struct here is read by
// shaders as std140 (uniforms) or std430 (storage) and written by C++ as is,
// so members are vec4/mat4 only: both layouts then agree with C++'s.
#ifndef PLANTFIELD_SHADERS_LAYOUTS_H
#define PLANTFIELD_SHADERS_LAYOUTS_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#endif

// The frame block of every colour pass is binding 0 of set 0.
#define BINDING_FRAME_UNIFORMS 0

struct FrameUniforms {
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPosition; // xyz world position, w: scene time in seconds
    vec4 sunDirection;   // xyz unit vector pointing toward the sun
    vec4 sunRadiance;    // rgb
    vec4 skyZenith;      // rgb radiance straight up
    vec4 skyHorizon;     // rgb radiance at the horizon
    vec4 groundAlbedo;   // rgb
    vec4 fog;            // x: density per metre, y: ground extent (half size, m)
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::FrameUniforms) == 2 * 64 + 7 * 16);
#endif

#endif
