// The physical model of a plant's skeleton (docs/PHYSICS.md), built with the
// plant models at load: the inputs of the physics passes and their CPU reference.
#pragma once

#include "engine/scene/scene.h"
#include "lsystem/turtle/plant_asset.h"
#include "shaders/shared/physics_layouts.h"

#include <vector>

namespace pf {

// Per joint of a PlantAsset: JointParams in the asset's plant space
// multiplied by `scale` (the species height scale the meshes got), so the
// skeleton matches the baked meshes. Mass ρ·π·r²·l (r the mean radius),
// inertia about the base of the subtree it turns (m·l²/3 for a joint that
// carries nothing; leaves weigh 0.2 kg/m²), stiffness from Joint::stiffness (@K, or
// Crankshaw's F(l, k)) when set, else beam theory E·π·r⁴/(4·l) with the base
// radius, damping 2·ζ·sqrt(k·I), drag area Cd·2·r·l plus the leaves and
// blades attached to the joint (their area times settings.leafDrag), subtree
// load from the joint's descendants at rest.
std::vector<gpu::JointParams> buildJointParams(const lsys::PlantAsset& asset, float scale,
                                               const PhysicsSettings& settings);

} // namespace pf
