// The shadow frames of the impostor atlas (docs/IMPOSTORS.md, "Shadow
// frames"): frame f of a model views it from the sun's elevation e at
// azimuth a = 2π·f/frames, so that its billboard in the shadow passes is one
// quad perpendicular to the sun direction, a true billboard in the sun's
// view. Shared by the bake (engine/field/impostor_bake.cpp) and the shadow
// passes' billboards (shaders/impostor_shadow.vert), which must agree on the
// frame's axes and extents texel for texel. GLSL and C++ (namespace gpu,
// glm) read this file.
#ifndef PLANTFIELD_SHADERS_IMPOSTOR_SHADOW_FRAME_H
#define PLANTFIELD_SHADERS_IMPOSTOR_SHADOW_FRAME_H

#include "field_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec3 = glm::vec3;
using glm::cos;
using glm::sin;
#define SHADOW_FRAME_FN inline
#else
#define SHADOW_FRAME_FN
#endif

// The axes of the orthographic view from azimuth `a` (plant space) and
// elevation e (sinE, cosE): it looks along −toSun; its right axis is the
// colour frames' (horizontal), its up axis the vertical tilted away from
// the sun, so that right, up and toSun are right-handed and orthonormal.
SHADOW_FRAME_FN vec3 shadowFrameToSun(float a, float sinE, float cosE) {
    return vec3(sin(a) * cosE, sinE, cos(a) * cosE);
}
SHADOW_FRAME_FN vec3 shadowFrameRight(float a) { return vec3(cos(a), 0.0f, -sin(a)); }
SHADOW_FRAME_FN vec3 shadowFrameUp(float a, float sinE, float cosE) {
    return vec3(-sin(a) * sinE, cosE, -cos(a) * sinE);
}

// The frame's centre: the middle of the model's box on the plant's axis,
// the point the billboard's plane passes through.
SHADOW_FRAME_FN vec3 shadowFrameCentre(vec4 impostorQuad) {
    return vec3(0.0f, 0.5f * (impostorQuad.y + impostorQuad.z), 0.0f);
}

// Half extents about the centre along right, up and toSun of the cylinder
// around the plant's axis that holds the box from every azimuth (radius
// impostorQuad.x, y from impostorQuad.y to .z): seen along the sun its
// height h shortens to h·cos e and its disc adds r·sin e either side.
SHADOW_FRAME_FN vec3 shadowFrameHalfExtents(vec4 impostorQuad, float sinE, float cosE) {
    float r = impostorQuad.x;
    float halfHeight = 0.5f * (impostorQuad.z - impostorQuad.y);
    return vec3(r, halfHeight * cosE + r * sinE, halfHeight * sinE + r * cosE);
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef SHADOW_FRAME_FN

#endif
