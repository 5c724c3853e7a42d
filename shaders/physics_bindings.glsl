// The descriptor set of shaders/physics.comp and shaders/pose.comp (bindings
// named in physics_layouts.h, built by engine/physics/physics_pass.cpp). What
// a pass only reads is bound as a uint texel buffer (texels.glsl says why).
#ifndef PHYSICS_BINDINGS_GLSL
#define PHYSICS_BINDINGS_GLSL
#include "shared/joint_physics.h"
#include "texels.glsl"

layout(set = 0, binding = PHYSICS_BINDING_UNIFORMS, std430) readonly buffer PhysicsBlock {
    PhysicsUniforms physics;
};
layout(set = 0, binding = PHYSICS_BINDING_PARAMS) uniform usamplerBuffer paramTexels;
layout(set = 0, binding = PHYSICS_BINDING_SKELETONS) uniform usamplerBuffer skeletonTexels;
layout(set = 0, binding = PHYSICS_BINDING_STATES, std430) buffer States {
    JointState states[];
};
layout(set = 0, binding = PHYSICS_BINDING_POSES, std430) buffer Poses {
    JointPose poses[];
};
layout(set = 0, binding = PHYSICS_BINDING_JOINT_SKELETON) uniform usamplerBuffer jointSkeletonTexels;
layout(set = 0, binding = PHYSICS_BINDING_JOINT_ORDER) uniform usamplerBuffer jointOrderTexels;
layout(set = 0, binding = PHYSICS_BINDING_STATE_TEXELS) uniform usamplerBuffer stateTexels;
layout(set = 0, binding = PHYSICS_BINDING_POSE_TEXELS) uniform usamplerBuffer poseTexels;

JointParams jointParamsAt(uint i) {
    int t = int(i) * JOINT_PARAMS_TEXELS;
    JointParams p;
    p.restBase = floatTexel(paramTexels, t);
    p.restRotation = floatTexel(paramTexels, t + 1);
    p.dynamics = floatTexel(paramTexels, t + 2);
    p.load = floatTexel(paramTexels, t + 3);
    p.aero = floatTexel(paramTexels, t + 4);
    p.links = texelFetch(paramTexels, t + 5);
    return p;
}

// The skeleton simulated joint `joint` belongs to.
Skeleton skeletonOfJoint(uint joint) {
    return skeletonFromTexels(skeletonTexels, texelFetch(jointSkeletonTexels, int(joint)).x);
}

JointState stateAt(uint i) {
    int t = int(i) * JOINT_STATE_TEXELS;
    return JointState(floatTexel(stateTexels, t), floatTexel(stateTexels, t + 1));
}

JointPose poseAt(uint i) {
    return poseFromTexels(poseTexels, i);
}

#endif
