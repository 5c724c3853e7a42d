#version 460
#extension GL_GOOGLE_include_directive : require
#include "joint_physics.h"

// Pose (DESIGN.md §5 pass 2): one invocation per simulated joint composes
// its pose from its own local map and its ancestors', walking up to the
// root (joint_physics.h). Reads only states, writes only its own pose.
// engine/plant_physics.h poseSkeletonsOnCpu is the CPU reference. Bindings:
// engine/physics_pass.cpp.
layout(local_size_x = PHYSICS_GROUP_SIZE) in;

layout(set = 0, binding = 0, std140) uniform PhysicsBlock {
    PhysicsUniforms physics;
};
layout(set = 0, binding = 1, std430) readonly buffer Params {
    JointParams params[];
};
layout(set = 0, binding = 2, std430) readonly buffer Skeletons {
    Skeleton skeletons[];
};
layout(set = 0, binding = 3, std430) readonly buffer States {
    JointState states[];
};
layout(set = 0, binding = 4, std430) writeonly buffer Poses {
    JointPose poses[];
};
layout(set = 0, binding = 5, std430) readonly buffer JointSkeletons {
    uint jointSkeleton[];
};

void main() {
    // Two-dimensional dispatch past maxComputeWorkGroupCount[0] groups.
    uint index = gl_WorkGroupID.y * gl_NumWorkGroups.x * PHYSICS_GROUP_SIZE + gl_GlobalInvocationID.x;
    if (index >= physics.counts.y) return;

    Skeleton sk = skeletons[jointSkeleton[index]];
    uint firstParam = sk.ids.y, firstState = sk.ids.w;
    uint joint = index - firstState;
    JointParams jp = params[firstParam + joint];
    JointPose p = jointLocalMap(jp, states[index]);
    for (uint k = jp.links.x; k != JOINT_NO_PARENT; k = params[firstParam + k].links.x)
        p = underParent(params[firstParam + k], states[firstState + k], p);
    poses[index] = p;
}
