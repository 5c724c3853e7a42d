// Camera and sky/sun settings, and the per-frame uniforms built from them.
#pragma once

#include "shaders/shared/layouts.h"

#include <glm/glm.hpp>

namespace pf {

struct Camera {
    glm::vec3 position{4.0f, 2.0f, 6.0f};
    glm::vec3 target{0.0f, 1.5f, 0.0f};
    float fovYDegrees = 45.0f;
    float nearPlane = 0.05f;
    float farPlane = 2000.0f;
};

struct Environment {
    float sunElevationDegrees = 38.0f;
    float sunAzimuthDegrees = 140.0f; // clockwise from -z (north) toward +x
    glm::vec3 sunRadiance{1.9f, 1.8f, 1.6f};
    glm::vec3 skyZenith{0.16f, 0.30f, 0.62f};
    glm::vec3 skyHorizon{0.62f, 0.72f, 0.85f};
    glm::vec3 groundAlbedo{0.13f, 0.22f, 0.055f};
    float fogDensity = 0.0025f;    // per metre
    float groundHalfSize = 400.0f; // metres
};

// An axis-aligned box in world metres: what a frame may show (the field's
// terrain and plants, fieldBox in engine/scene/field_content.h).
struct SceneBox {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// The camera with a depth range that holds `box` however far away it looks
// from: a depth buffer of floats resolves depths only down to about n/d of
// 1e-7, so from millions of metres with the scene's near plane every depth
// rounds to the far plane. A camera within 10^4 near planes of the box (or
// inside it) is returned unchanged; farther out, the near plane moves to half
// the distance to the box and the far plane to at least its farthest corner.
Camera withDepthRangeFor(const Camera& camera, const SceneBox& box);

// Unit vector toward the sun.
glm::vec3 sunDirection(const Environment& env);

// World → view space (right-handed, looking down −z), the image's up from
// lsys::viewUp: world +y, or north (−z) looking straight down.
glm::mat4 viewMatrix(const Camera& camera);
// Perspective for a viewport of `viewport` pixels (width, height): standard
// depth, 0 at the near plane and 1 at the far plane (perspectiveRH_ZO).
glm::mat4 projectionMatrix(const Camera& camera, glm::uvec2 viewport);

// Projection for a viewport of `viewport` pixels (width, height) with negative
// height (y up in clip space) and depth in [0, 1].
gpu::FrameUniforms makeFrameUniforms(const Camera& camera, const Environment& env, glm::uvec2 viewport, float time);

} // namespace pf
