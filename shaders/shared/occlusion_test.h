// The occlusion test of one bounding sphere against the depth pyramid
// (docs/CULLING.md, "Occlusion culling"), shared by shaders/cull_late.comp and
// the CPU reference pf::sphereOccludedOnCpu so both make the same choice with
// the same float operations. GLSL and C++ (namespace gpu, glm) read this
// file; the texel fetches themselves are the caller's.
//
// Depth is standard (0 at the near plane, 1 at the far plane, cleared to 1,
// less-than test: engine/scene/camera.cpp), so the pyramid keeps the largest
// (farthest) depth of the pixels under each texel, and a sphere is hidden when
// its nearest point lies behind the farthest depth of every pixel its screen
// rectangle covers.
#ifndef PLANTFIELD_SHADERS_OCCLUSION_TEST_H
#define PLANTFIELD_SHADERS_OCCLUSION_TEST_H

#include "field_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using uvec2 = glm::uvec2;
using glm::clamp;
using glm::floor;
using glm::sqrt;
#define OCCLUSION_FN inline
#else
#define OCCLUSION_FN
#endif

// True when the sphere (view space: centre xyz, radius w; the camera looks
// down −z) comes within the near plane: its projection is unbounded there,
// and it is never called occluded.
OCCLUSION_FN bool sphereNearCamera(vec4 viewSphere, float nearPlane) {
    return -viewSphere.z - viewSphere.w < nearPlane;
}

// The sphere's screen rectangle as fractions of the viewport (min xy, max
// zw; x to the right, y down from the top row, as the framebuffer's rows
// run under the colour pass's flipped viewport): the tangent lines from the
// eye to the sphere in the xz and yz planes (Mara and McGuire 2013, "2D
// Polyhedral Bounds of a Clipped, Perspective-Projected 3D Sphere", §3),
// then P[0][0] and P[1][1]. Only when !sphereNearCamera.
OCCLUSION_FN vec4 sphereScreenRect(vec4 viewSphere, vec4 projection) {
    float d = -viewSphere.z; // distance in front of the eye
    float r = viewSphere.w;
    float dr2 = d * d - r * r;
    float tx = sqrt(viewSphere.x * viewSphere.x + dr2);
    float minX = (tx * viewSphere.x - r * d) / (tx * d + r * viewSphere.x);
    float maxX = (tx * viewSphere.x + r * d) / (tx * d - r * viewSphere.x);
    float ty = sqrt(viewSphere.y * viewSphere.y + dr2);
    float minY = (ty * viewSphere.y - r * d) / (ty * d + r * viewSphere.y);
    float maxY = (ty * viewSphere.y + r * d) / (ty * d - r * viewSphere.y);
    // Clip x and y → [0, 1]; y flips (clip +y is the top row).
    return vec4(minX * projection.x * 0.5f + 0.5f, 0.5f - maxY * projection.y * 0.5f, maxX * projection.x * 0.5f + 0.5f,
                0.5f - minY * projection.y * 0.5f);
}

// The pixels the rectangle covers, clamped to the viewport: min xy, max zw.
OCCLUSION_FN uvec4 rectPixels(vec4 rect, vec2 viewport) {
    vec4 pixels = floor(rect * vec4(viewport, viewport));
    vec4 last = vec4(viewport - vec2(1.0f), viewport - vec2(1.0f));
    return uvec4(clamp(pixels, vec4(0.0f), last));
}

// The finest pyramid level at which the pixels fall in at most 2×2 texels.
// Level l halves the one below, rounding up, from level 0 at half the
// viewport, so its texel (x, y) holds pixels (x, y)·2^(l+1) to
// (x + 1, y + 1)·2^(l+1) − 1: a pixel p lies in texel p >> (l + 1). The top
// level is one texel, so the loop ends there at the latest.
OCCLUSION_FN uint pyramidLevel(uvec4 pixels, uint levels) {
    uint level = 0u;
    while (level + 1u < levels && (((pixels.z >> (level + 1u)) - (pixels.x >> (level + 1u))) > 1u ||
                                   ((pixels.w >> (level + 1u)) - (pixels.y >> (level + 1u))) > 1u))
        ++level;
    return level;
}

// The depth-buffer value of the sphere's nearest point (its centre's
// distance less the radius): clip z / clip w of perspectiveRH_ZO.
OCCLUSION_FN float sphereNearestDepth(vec4 viewSphere, vec4 projection) {
    float d = -viewSphere.z - viewSphere.w;
    return (projection.w - projection.z * d) / d;
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef OCCLUSION_FN

#endif
