// GPU data of the plant physics (docs/PHYSICS.md), shared by GLSL and C++ like
// field_layouts.h: vec4/uvec4 members only.
//
// A model's skeleton is its joints (one per segment). A simulated copy of a
// skeleton (a Skeleton) has one JointState and one JointPose per joint. The
// physics pass advances every simulated joint in parallel; the pose pass
// then turns the local rotations into one affine map per joint, which the
// vertex shaders apply to the joint's vertices (skinning).
#ifndef PLANTFIELD_SHADERS_PHYSICS_LAYOUTS_H
#define PLANTFIELD_SHADERS_PHYSICS_LAYOUTS_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using uint = uint32_t;
#endif

#define PHYSICS_GROUP_SIZE 64

// Descriptor bindings of the physics and pose passes (their set 0). What a
// pass only reads is a uint texel buffer (texels.glsl says why).
#define PHYSICS_BINDING_UNIFORMS 0       // PhysicsUniforms
#define PHYSICS_BINDING_PARAMS 1         // JointParams[], texels
#define PHYSICS_BINDING_SKELETONS 2      // Skeleton[], texels
#define PHYSICS_BINDING_STATES 3         // JointState[], written
#define PHYSICS_BINDING_POSES 4          // JointPose[], written
#define PHYSICS_BINDING_JOINT_SKELETON 5 // uint per simulated joint: its Skeleton, texels
#define PHYSICS_BINDING_JOINT_ORDER 6    // uint per simulated joint, level by level, texels
#define PHYSICS_BINDING_STATE_TEXELS 7   // the states again, as texels
#define PHYSICS_BINDING_POSE_TEXELS 8    // the poses again, as texels

// A physics dispatch takes 1 to PHYSICS_MAX_DISPATCH_SUB_STEPS sub-steps, its
// pipeline's loop count a specialization constant (PHYSICS_SUB_STEPS_CONSTANT_ID),
// one pipeline per count: a loop bound the compiler knows is unrolled, and
// lavapipe compiles a shader again whenever push constants that bound a
// loop change (it inlines their values), at every dispatch.
#define PHYSICS_MAX_DISPATCH_SUB_STEPS 8u
#define PHYSICS_SUB_STEPS_CONSTANT_ID 0

// Texels of 16 bytes (R32G32B32A32_UINT views) each struct below takes in
// the texel views the passes and the draw shaders read it through.
#define JOINT_PARAMS_TEXELS 6
#define JOINT_STATE_TEXELS 2
#define JOINT_POSE_TEXELS 2
#define SKELETON_TEXELS 3
#define JOINT_NO_PARENT 0xFFFFFFFFu
// Skeleton::ids.w of a plant without a simulated skeleton: its vertices stay at rest.
#define NO_SKELETON 0xFFFFFFFFu

// One joint of a model's skeleton, in plant space before instance scale.
// Quaternions are xyzw. The segment's rest frame R has local +Y along the
// segment (lsystem/turtle/plant_asset.h Frame).
struct JointParams {
    vec4 restBase;     // xyz base of the segment, w length (m)
    vec4 restRotation; // quaternion R: the segment's rest frame in plant space
    vec4
        dynamics; // x mass m (kg), y inertia about the base I (kg·m²), z stiffness k (N·m/rad), w damping c (N·m·s/rad)
    vec4 load;   // xyz centre of mass of the joint's subtree (itself and all it carries) relative to its base, in its
                 // rest local frame (m); w subtree mass (kg)
    vec4 aero;   // x drag area Cd·A (m², the segment's and its leaves'), y distance from the base to the centre of
                 // pressure (m), zw 0
    uvec4 links; // x parent joint index in the model or JOINT_NO_PARENT, y depth (roots 0), zw 0
};

// One simulated joint: its rotation away from rest, in its local frame, and
// its angular velocity. Identity and zero at rest.
struct JointState {
    vec4 rotation;        // quaternion q: the joint's current local frame is R·q (times its parent's motion)
    vec4 angularVelocity; // xyz rad/s in the joint's local frame, w 0
};

// The pose of one simulated joint: the affine map taking rest plant-space
// points of the segment (and everything attached to it) to where they are
// now: x' = rotate(rotation, x) + translation.
struct JointPose {
    vec4 rotation;    // quaternion
    vec4 translation; // xyz, w 0
};

// One simulated copy of a model's skeleton.
struct Skeleton {
    uvec4 ids;      // x model, y first JointParams of the model, z joints, w first JointState/JointPose
    vec4 placement; // xyz world position where the plant stands (the wind is sampled around it), w yaw (radians)
    vec4 scale;     // x instance scale, yzw 0
};

// Bound as a read-only storage buffer, not a uniform block (docs/ARCHITECTURE.md,
// "What a shader may branch on").
struct PhysicsUniforms {
    vec4 gravity; // xyz m/s² (world), w air density (kg/m³)
    vec4 wind;    // x, z: mean wind velocity (m/s, world); y gust strength (fraction of the speed); w gust front speed
                  // (m/s)
    vec4 windDetail; // x turbulence (fraction of the speed), y gust wavelength (m), z time (s) at the start of this
                     // dispatch, w sub-step (s)
    uvec4 counts;    // x skeletons, y simulated joints, z sub-steps this dispatch, w 0
};

// The push constants of one physics dispatch: when its sub-steps start and
// how many it takes (the shader's count is its pipeline's, which is chosen by
// this one). A frame's catch-up and its own steps are several dispatches in
// one command buffer; the rest of PhysicsUniforms holds for all.
struct PhysicsDispatch {
    float time;    // s: the first sub-step's time (PhysicsUniforms::windDetail.z of this dispatch)
    uint subSteps; // PhysicsUniforms::counts.z of this dispatch
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::JointParams) == JOINT_PARAMS_TEXELS * 16);
static_assert(sizeof(gpu::JointState) == JOINT_STATE_TEXELS * 16);
static_assert(sizeof(gpu::JointPose) == JOINT_POSE_TEXELS * 16);
static_assert(sizeof(gpu::Skeleton) == SKELETON_TEXELS * 16);
static_assert(sizeof(gpu::PhysicsUniforms) == 64);
static_assert(sizeof(gpu::PhysicsDispatch) == 8);
#endif

#endif
