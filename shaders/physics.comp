#version 460
#extension GL_GOOGLE_include_directive : require
#include "physics_bindings.glsl"

// Physics, the frame's first pass (docs/PHYSICS.md): one invocation per
// simulated joint takes the dispatch's sub-steps of stepJoint, its state
// held in registers between them (prepareJointStep once per joint). Every joint
// reads its parent's rotation and its own base from the poses at entry (written
// by the previous pose pass) and writes only its own state, so the joints of a
// dispatch are independent. engine/physics/plant_physics.h stepSkeletonsOnCpu is the
// CPU reference.
layout(local_size_x = PHYSICS_GROUP_SIZE) in;

// This dispatch's start time and sub-step count; the uniforms give the rest.
layout(push_constant) uniform DispatchBlock {
    PhysicsDispatch dispatch;
};
// The same count, fixed for this pipeline (physics_layouts.h says why).
layout(constant_id = PHYSICS_SUB_STEPS_CONSTANT_ID) const uint kSubSteps = 1u;

void main() {
    // Two-dimensional dispatch past maxComputeWorkGroupCount[0] groups.
    uint index = gl_WorkGroupID.y * gl_NumWorkGroups.x * PHYSICS_GROUP_SIZE + gl_GlobalInvocationID.x;
    if (index >= physics.counts.y) return;

    Skeleton sk = skeletonOfJoint(index);
    if (!skeletonInUse(sk)) return;
    uint joint = index - sk.ids.w;
    JointParams jp = jointParamsAt(sk.ids.y + joint);
    uint parent = jp.links.x;
    vec4 parentRotation = parent == JOINT_NO_PARENT ? vec4(0.0f, 0.0f, 0.0f, 1.0f) : poseAt(sk.ids.w + parent).rotation;
    vec3 base = posePoint(poseAt(index), jp.restBase.xyz);

    PhysicsUniforms u = physics;
    u.windDetail.z = dispatch.time;
    u.counts.z = kSubSteps;
    float dt = u.windDetail.w;
    JointState s = stateAt(index);
    JointStep c = prepareJointStep(jp, parentRotation, base, s, sk, u, dt);
    for (uint step = 0u; step < kSubSteps; ++step) s = stepJoint(c, s, step, dt);
    states[index] = endJointFrame(s);
}
