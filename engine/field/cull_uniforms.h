// What the cull pass (cull_pass.h) is given each frame, made on the CPU:
// the frustum's planes, the camera's pixels per metre, its LOD inputs and
// what the late phase's occlusion test needs (docs/CULLING.md). CPU only.
#pragma once

#include "engine/scene/camera.h"
#include "shaders/shared/field_layouts.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace pf {

// The six planes of a view-projection (Vulkan clip space, depth 0..1),
// normalised, normals pointing inward.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj);

// Pixels per metre at one metre of distance of a camera with this vertical
// field of view over this many pixels (CullUniforms::camera.w).
float pixelsPerMetre(float fovYRadians, uint32_t viewportHeight);

// Per frame, before record: frustum, camera, forced LOD, delta time.
// `firstFrame` resets every instance's LOD state to settled at its target LOD
// (and has the early phase draw nothing). counts.x and counts.y (instances,
// templates) are left 0: setCullUniforms fills them from the pass.
gpu::CullUniforms makeCullUniforms(const glm::mat4& viewProj, const glm::vec3& cameraPosition, float fovYRadians,
                                   uint32_t viewportHeight, float deltaSeconds, bool firstFrame,
                                   uint32_t forcedLod = 0xFFFFFFFFu);
// What the late phase's occlusion test needs (CullUniforms::view, projection,
// viewport): the camera's view and projection (perspectiveRH_ZO), the
// viewport, its near plane and the levels of its depth pyramid.
void setOcclusionUniforms(gpu::CullUniforms& uniforms, const glm::mat4& view, const glm::mat4& projection,
                          glm::uvec2 viewport, float nearPlane, uint32_t pyramidLevels);
// Both for the frame's camera (`viewProj` its view-projection, as the frame
// uniforms have it) over `viewport`, its depth pyramid's levels
// (depthPyramidExtents).
gpu::CullUniforms cameraCullUniforms(const glm::mat4& viewProj, const Camera& camera, glm::uvec2 viewport,
                                     float deltaSeconds, bool firstFrame, uint32_t forcedLod);

} // namespace pf
