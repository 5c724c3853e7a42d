#version 460
#extension GL_GOOGLE_include_directive : require
#include "joint_physics.h"

// Pose (DESIGN.md §5 pass 2), one dispatch per depth level from the roots
// down: one invocation per joint of the level composes its parent's pose,
// written by the previous level's dispatch, with its own local map
// (joint_physics.h composeWithParent). jointOrder lists the simulated joints
// level after level; the push constants say which run of it this dispatch
// poses. engine/plant_physics.h poseSkeletonsOnCpu is the CPU reference.
// Bindings: engine/physics_pass.cpp.
layout(local_size_x = PHYSICS_GROUP_SIZE) in;

layout(push_constant) uniform Level {
    uvec2 level; // x first entry of jointOrder, y joints in the level
};

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
layout(set = 0, binding = 4, std430) buffer Poses {
    JointPose poses[];
};
layout(set = 0, binding = 5, std430) readonly buffer JointSkeletons {
    uint jointSkeleton[];
};
layout(set = 0, binding = 6, std430) readonly buffer JointOrder {
    uint jointOrder[];
};

void main() {
    // Two-dimensional dispatch past maxComputeWorkGroupCount[0] groups.
    uint k = gl_WorkGroupID.y * gl_NumWorkGroups.x * PHYSICS_GROUP_SIZE + gl_GlobalInvocationID.x;
    if (k >= level.y) return;

    uint index = jointOrder[level.x + k];
    Skeleton sk = skeletons[jointSkeleton[index]];
    if (!skeletonInUse(sk)) return;
    JointParams jp = params[sk.ids.y + index - sk.ids.w];
    JointPose parent;
    if (jp.links.x == JOINT_NO_PARENT) {
        parent.rotation = vec4(0.0f, 0.0f, 0.0f, 1.0f);
        parent.translation = vec4(0.0f);
    } else {
        parent = poses[sk.ids.w + jp.links.x];
    }
    poses[index] = composeWithParent(parent, jp, states[index]);
}
