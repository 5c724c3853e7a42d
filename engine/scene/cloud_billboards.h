// What the cloud pass draws in one frame (engine/field/cloud_pass.h): every
// sphere of the scene's clouds where the wind has carried it by then,
// farthest first, so that blending them in order composites them back to
// front.
#pragma once

#include "engine/scene/scene.h"
#include "shaders/shared/cloud_layouts.h"

#include <glm/glm.hpp>

#include <vector>

namespace pf {

// Every sphere of `clouds`, moved by meanWindVelocity(wind) · time, ordered
// by depth along the view direction `forward` from `camera`, farthest first;
// spheres at the same depth keep the order of the clouds and of their
// spheres, so a frame at the same time and view is the same list, bit for bit.
std::vector<gpu::CloudBillboard> cloudBillboards(const std::vector<Cloud>& clouds, const Wind& wind, float time,
                                                 const glm::vec3& camera, const glm::vec3& forward);

} // namespace pf
