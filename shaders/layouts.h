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

// Descriptor bindings of the scene's one descriptor set.
#define BINDING_FRAME_UNIFORMS 0
#define BINDING_SEGMENT_INSTANCES 1
#define BINDING_MESH_VERTICES 2

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

// One drawn plant segment: a cone frustum from start to end.
struct SegmentInstance {
    vec4 startRadius; // xyz start point, w radius at start
    vec4 endRadius;   // xyz end point, w radius at end
    vec4 albedo;      // rgb, a unused
};

// Unit cylinder mesh vertex: position in the segment's frame (y along the
// axis from 0 to 1, xz on the unit circle), normal in the same frame; w = 1
// marks side vertices whose normal tilts with the cone's taper.
struct MeshVertex {
    vec4 position;
    vec4 normal;
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::FrameUniforms) == 2 * 64 + 7 * 16);
static_assert(sizeof(gpu::SegmentInstance) == 48);
static_assert(sizeof(gpu::MeshVertex) == 32);
#endif

#endif
