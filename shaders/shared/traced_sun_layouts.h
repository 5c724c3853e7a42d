// GPU layout of the traced-sun pass (engine/field/traced_sun_pass.h,
// shaders/traced_sun.comp), shared by GLSL and C++: one ray to the sun per
// pixel, through the field's graph (engine/raytrace/field_graph.h), whose
// buffers take bindings RAYTRACE_BINDING_NODES … _TRIANGLES of the same set.
#ifndef PLANTFIELD_SHADERS_TRACED_SUN_LAYOUTS_H
#define PLANTFIELD_SHADERS_TRACED_SUN_LAYOUTS_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#endif

#define TRACED_SUN_GROUP_SIZE 8          // invocations a side of a workgroup, one a pixel
#define TRACED_SUN_BINDING_ORIGINS 8     // rgba32f storage image: xyz where the ray starts, w 1 (0: no ray)
#define TRACED_SUN_BINDING_VISIBILITY 9  // r32f storage image: 1 lit, 0 in shadow
#define TRACED_SUN_LEAF_CARD_MATERIAL 1u // a field primitive's material (its SURFACE_* kind) cut by leafCutOut

struct TracedSunPush {
    vec4 sun;    // xyz towards the sun (unit), w the rays' length (m)
    uvec4 frame; // x width, y height (pixels), z the field's root node, w 0
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::TracedSunPush) == 32);
#endif

#endif
