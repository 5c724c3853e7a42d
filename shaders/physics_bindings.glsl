// The descriptor set of shaders/physics.comp and shaders/pose.comp (built by
// engine/physics/physics_pass.cpp in this order). What a pass only reads is bound
// as a uint texel buffer (texels.glsl says why).
#ifndef PHYSICS_BINDINGS_GLSL
#define PHYSICS_BINDINGS_GLSL
#include "joint_physics.h"
#include "texels.glsl"

layout(set = 0, binding = 0, std140) uniform PhysicsBlock {
    PhysicsUniforms physics;
};
layout(set = 0, binding = 1) uniform usamplerBuffer paramTexels;    // JointParams[], 6 texels each
layout(set = 0, binding = 2) uniform usamplerBuffer skeletonTexels; // Skeleton[], 3 texels each
layout(set = 0, binding = 3, std430) buffer States {
    JointState states[];
};
layout(set = 0, binding = 4, std430) buffer Poses {
    JointPose poses[];
};
layout(set = 0, binding = 5) uniform usamplerBuffer jointSkeletonTexels; // uint per simulated joint
layout(set = 0, binding = 6) uniform usamplerBuffer jointOrderTexels;    // uint per simulated joint, level by level
layout(set = 0, binding = 7) uniform usamplerBuffer stateTexels;         // the states, 2 texels each
layout(set = 0, binding = 8) uniform usamplerBuffer poseTexels;          // the poses, 2 texels each

JointParams jointParamsAt(uint i) {
    int t = int(i) * 6;
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
    return JointState(floatTexel(stateTexels, int(i) * 2), floatTexel(stateTexels, int(i) * 2 + 1));
}

JointPose poseAt(uint i) {
    return poseFromTexels(poseTexels, i);
}

#endif
