// GPU layout of the traced-sun pass (engine/field/raytraced_sun_pass.h,
// shaders/raytraced_sun.comp), shared by GLSL and C++: one ray to the sun per
// pixel, through the field's graph (engine/raytrace/field_graph.h), whose
// buffers take bindings RAYTRACE_BINDING_NODES … _TRIANGLES of the same set.
#ifndef PLANTFIELD_SHADERS_RAYTRACED_SUN_LAYOUTS_H
#define PLANTFIELD_SHADERS_RAYTRACED_SUN_LAYOUTS_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#endif

#define RAYTRACED_SUN_GROUP_SIZE 8          // invocations a side of a workgroup, one a pixel
#define RAYTRACED_SUN_BINDING_ORIGINS 8     // rgba32f storage image: xyz where the ray starts, w 1 (0: no ray)
#define RAYTRACED_SUN_BINDING_VISIBILITY 9  // r32f storage image: 1 lit, 0 in shadow
#define RAYTRACED_SUN_LEAF_CARD_MATERIAL 1u // a field primitive's material (its SURFACE_* kind) cut by leafCutOut

struct RaytracedSunPush {
    vec4 sun;    // xyz towards the sun (unit), w the rays' length (m)
    uvec4 frame; // x width, y height (pixels), z the field's root node, w 0
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::RaytracedSunPush) == 32);
#endif

#endif
