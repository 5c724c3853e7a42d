// Which impostors the frame's shadow map cannot reach (IMPOSTOR_PART_SUNLIT),
// shared by shaders/impostor.vert and the tests like lod_select.h. Outside
// the map's square or beyond its far plane sunVisibilityAt (field_common.glsl)
// is 1, so a plant whose every fragment lies there is drawn by a pipeline
// with no shadow lookup: on a CPU rasteriser a branch around the lookup
// saves nothing (every lane of a SIMD block runs both sides), while another
// pipeline does, and most impostors stand beyond the map's 120 m.
#ifndef PLANTFIELD_SHADERS_SUNLIT_SELECT_H
#define PLANTFIELD_SHADERS_SUNLIT_SELECT_H

#include "field_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec3 = glm::vec3;
using glm::abs;
using glm::length;
#define SUNLIT_SELECT_FN inline
#else
#define SUNLIT_SELECT_FN
#endif

// Metres an impostor's drawn quad may reach beyond its plant's bounding
// sphere, per metre of radius: the wind's lean of its top (impostor.vert), a
// few tenths of a metre on a ten-metre crown, well inside a quarter.
#define SUNLIT_SWAY_MARGIN 0.25f
// Shadow-map texels sunMapPosition offsets a fragment along its normal
// (1.5), with room to spare.
#define SUNLIT_OFFSET_TEXELS 2.0f

// True when no point within `margin` metres of the sphere projects into the
// orthographic `sunViewProj`'s square (clip x, y in [-1, 1]) in front of its
// far plane (clip z ≤ 1).
SUNLIT_SELECT_FN bool sphereBeyondShadowMap(vec4 sphere, mat4 sunViewProj, float margin) {
    vec4 clip = sunViewProj * vec4(vec3(sphere), 1.0f);
    float r = sphere.w + margin;
    // Clip units per metre along each axis: the rows of the linear part.
    float sx = length(vec3(sunViewProj[0][0], sunViewProj[1][0], sunViewProj[2][0]));
    float sy = length(vec3(sunViewProj[0][1], sunViewProj[1][1], sunViewProj[2][1]));
    float sz = length(vec3(sunViewProj[0][2], sunViewProj[1][2], sunViewProj[2][2]));
    return abs(clip.x) - r * sx > 1.0f || abs(clip.y) - r * sy > 1.0f || clip.z - r * sz > 1.0f;
}

// The part an impostor belongs to: sunlit where the map cannot reach it or
// shadows are off (`texelMetres` 0), shadowed otherwise.
SUNLIT_SELECT_FN uint impostorPartOf(vec4 sphere, mat4 sunViewProj, float texelMetres, bool shadows) {
    if (!shadows) return IMPOSTOR_PART_SUNLIT;
    float margin = SUNLIT_SWAY_MARGIN * sphere.w + SUNLIT_OFFSET_TEXELS * texelMetres;
    return sphereBeyondShadowMap(sphere, sunViewProj, margin) ? IMPOSTOR_PART_SUNLIT : IMPOSTOR_PART_SHADOWED;
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef SUNLIT_SELECT_FN

#endif
