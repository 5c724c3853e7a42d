// Simulated skeletons and the CPU reference of the GPU physics and pose
// passes (docs/PHYSICS.md, after Crankshaw 2020, ch. 6): the same per-joint
// math (shaders/shared/joint_physics.h), one joint after another, over the
// parameters of engine/scene/joint_params.h.
#pragma once

#include "engine/scene/joint_params.h"
#include "shaders/shared/physics_layouts.h"

#include <cstdint>
#include <vector>

namespace pf {

// Simulated skeletons on the CPU: the same arrays the GPU pass holds.
struct SkeletonSet {
    std::vector<gpu::JointParams> params; // every model's joints, model after model
    std::vector<gpu::Skeleton> skeletons; // simulated copies
    std::vector<gpu::JointState> states;  // per simulated joint (Skeleton::ids.w + joint)
    std::vector<gpu::JointPose> poses;    // per simulated joint
    std::vector<uint32_t> jointSkeleton;  // per simulated joint: its skeleton
};

// Adds a simulated copy of the model whose joints start at params[firstParam]
// (`joints` of them), at rest. Returns the skeleton index.
uint32_t addSkeleton(SkeletonSet& set, uint32_t model, uint32_t firstParam, uint32_t joints, const glm::vec3& position,
                     float yaw, float scale);

// Metres between gust fronts (PhysicsUniforms::windDetail.y): gusts a few
// seconds apart at typical gust front speeds of 4–8 m/s.
inline constexpr float kGustWavelength = 40.0f;

// The uniforms for a dispatch of `subSteps` steps of `dt` seconds from `time`.
gpu::PhysicsUniforms makePhysicsUniforms(const Wind& wind, const PhysicsSettings& settings, float time, float dt,
                                         uint32_t subSteps, uint32_t skeletons, uint32_t joints);

// What the GPU does per frame: every joint takes u.counts.z sub-steps
// (stepJoint) against the poses at entry, then all poses are recomputed.
void stepSkeletonsOnCpu(SkeletonSet& set, const gpu::PhysicsUniforms& u);
void poseSkeletonsOnCpu(SkeletonSet& set);

// Sub-steps that take the simulation from time a to time b (the fixed
// step settings.subStep; b ≥ a), so a capture at time T is the same
// however it was reached in whole sub-steps.
// It is subStepsUntil(b) − subStepsUntil(a), where subStepsUntil(t) =
// floor(t·n + kSubStepRoundingSlack) (0 before time 0), n = 1/subStep
// rounded to a whole number when the float sub-step is 1/n within float
// precision (1/240 s as a float is slightly more than 1/240, and 1 s must
// still be 240 steps); the slack forgives a time summed from frames that
// lands a rounding error short of a step. Pass subStepsUntil(a)·subStep as
// the dispatch's time so the wind is sampled on the same grid however the
// frames fall.
uint32_t subStepsBetween(double a, double b, const PhysicsSettings& settings);
uint64_t subStepsUntil(double t, const PhysicsSettings& settings);
inline constexpr double kSubStepRoundingSlack = 1e-6;

} // namespace pf
