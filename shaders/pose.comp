#version 460
#extension GL_GOOGLE_include_directive : require
#include "physics_bindings.glsl"

// Pose, the frame's second pass, one dispatch per depth level from the roots
// down: one invocation per joint of the level composes its parent's pose,
// written by the previous level's dispatch, with its own local map
// (joint_physics.h composeWithParent). jointOrder lists the simulated joints
// level after level; the push constants say which run of it this dispatch
// poses. engine/physics/plant_physics.h poseSkeletonsOnCpu is the CPU reference.
layout(local_size_x = PHYSICS_GROUP_SIZE) in;

layout(push_constant) uniform Level {
    uvec2 level; // x first entry of jointOrder, y joints in the level
};

void main() {
    // Two-dimensional dispatch past maxComputeWorkGroupCount[0] groups.
    uint k = gl_WorkGroupID.y * gl_NumWorkGroups.x * PHYSICS_GROUP_SIZE + gl_GlobalInvocationID.x;
    if (k >= level.y) return;

    uint index = texelFetch(jointOrderTexels, int(level.x + k)).x;
    Skeleton sk = skeletonOfJoint(index);
    if (!skeletonInUse(sk)) return;
    JointParams jp = jointParamsAt(sk.ids.y + index - sk.ids.w);
    JointPose parent;
    if (jp.links.x == JOINT_NO_PARENT) {
        parent.rotation = vec4(0.0f, 0.0f, 0.0f, 1.0f);
        parent.translation = vec4(0.0f);
    } else {
        parent = poseAt(sk.ids.w + jp.links.x);
    }
    poses[index] = composeWithParent(parent, jp, stateAt(index));
}
