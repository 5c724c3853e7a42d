// The views of the impostor atlas (docs/IMPOSTORS.md, "Rings" and "Shadow
// frames"): every frame looks at a model orthographically from azimuth a
// about +y and elevation e above the horizon. The colour frames lie on
// IMPOSTOR_RINGS rings of elevation, IMPOSTOR_RING_STEP apart from the
// horizon up, so a plant seen from above is drawn from a frame baked from
// above (the octahedral impostors of game engines, in rings: a card seen
// from above shows the crown foreshortened, like a palm). The shadow frames
// lie on the sun's elevation. A billboard is one quad perpendicular to its
// frame's direction through the frame's centre. Shared by the bake
// (engine/field/impostor_bake.cpp) and the billboards (shaders/impostor.vert,
// shaders/impostor_shadow.vert), which must agree on the frame's axes and
// extents texel for texel. GLSL and C++ (namespace gpu, glm) read this file.
#ifndef PLANTFIELD_SHADERS_IMPOSTOR_FRAME_H
#define PLANTFIELD_SHADERS_IMPOSTOR_FRAME_H

#include "field_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec3 = glm::vec3;
using glm::clamp;
using glm::cos;
using glm::mod;
using glm::round;
using glm::sin;
#define IMPOSTOR_FRAME_FN inline
#else
#define IMPOSTOR_FRAME_FN
#endif

// Rings of colour frames at elevations 0°, 30° and 60°: a view between two
// rings is at most 15° from its frame, where a card's height is still
// within 3.5 % of the frame's (cos 15°).
#define IMPOSTOR_RINGS 3u
#define IMPOSTOR_RING_STEP 0.52359878f // radians (30°)

// The azimuth of frame f of n around the plant: 2π·f/n.
IMPOSTOR_FRAME_FN float impostorFrameAzimuth(uint f, uint n) { return 6.28318531f * float(f) / float(n); }

// The axes of the orthographic view from azimuth `a` (plant space) and
// elevation e (sinE, cosE): it looks along −toView; its right axis is
// horizontal, its up axis the vertical tilted away from the view, so that
// right, up and toView are right-handed and orthonormal. At e = 0, toView
// is (sin a, 0, cos a) and up is +y (impostor_atlas.h's frame convention).
IMPOSTOR_FRAME_FN vec3 impostorFrameToView(float a, float sinE, float cosE) {
    return vec3(sin(a) * cosE, sinE, cos(a) * cosE);
}
IMPOSTOR_FRAME_FN vec3 impostorFrameRight(float a) { return vec3(cos(a), 0.0f, -sin(a)); }
IMPOSTOR_FRAME_FN vec3 impostorFrameUp(float a, float sinE, float cosE) {
    return vec3(-sin(a) * sinE, cosE, -cos(a) * sinE);
}

// The frame's centre: the middle of the model's box on the plant's axis,
// the point the billboard's plane passes through.
IMPOSTOR_FRAME_FN vec3 impostorFrameCentre(vec4 impostorQuad) {
    return vec3(0.0f, 0.5f * (impostorQuad.y + impostorQuad.z), 0.0f);
}

// Half extents about the centre along right, up and toView of the cylinder
// around the plant's axis that holds the box from every azimuth (radius
// impostorQuad.x, y from impostorQuad.y to .z): seen from elevation e its
// height h shortens to h·cos e and its disc adds r·sin e either side.
IMPOSTOR_FRAME_FN vec3 impostorFrameHalfExtents(vec4 impostorQuad, float sinE, float cosE) {
    float r = impostorQuad.x;
    float halfHeight = 0.5f * (impostorQuad.z - impostorQuad.y);
    return vec3(r, halfHeight * cosE + r * sinE, halfHeight * sinE + r * cosE);
}

// The frame of n whose azimuth is nearest `azimuth` (radians, any turn):
// the nearest, not a blend of two, since frames are 30° apart and one
// texture fetch a pixel is what a CPU rasteriser can afford.
IMPOSTOR_FRAME_FN uint impostorNearestFrame(float azimuth, uint n) {
    float t = mod(azimuth / 6.28318531f * float(n), float(n));
    return uint(round(t)) % n;
}

// The elevation of ring r (radians).
IMPOSTOR_FRAME_FN float impostorRingElevation(uint ring) { return float(ring) * IMPOSTOR_RING_STEP; }

// The ring whose elevation is nearest `elevation` (radians; views from
// below the horizon take the lowest ring).
IMPOSTOR_FRAME_FN uint impostorRingOf(float elevation) {
    return uint(clamp(round(elevation / IMPOSTOR_RING_STEP), 0.0f, float(IMPOSTOR_RINGS - 1u)));
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef IMPOSTOR_FRAME_FN

#endif
