// The physics of one joint and the pose of a skeleton (docs/PHYSICS.md:
// Crankshaw 2020's model, its errata corrected), written once for
// shaders/physics.comp, shaders/pose.comp and the CPU reference
// (engine/physics/plant_physics.h), so both make the same float operations. GLSL and
// C++ (namespace gpu, glm) read this file; float literals carry an f suffix so
// C++ does not widen them.
//
// Model, per joint j with rest frame R (plant space, local +Y along the
// segment) and rotation q away from rest (local frame):
// - its current frame is L = Dp·R·q, Dp the parent's pose rotation at the
//   start of the frame (identity for a root);
// - external torque about its base, plant space: the wind's drag on the
//   segment and its leaves, F = ½·ρ·CdA·|v|·v at the centre of pressure c
//   (v = wind − the point's own velocity), plus the weight of the subtree it
//   carries, M·g at its centre of mass (rest shape, carried along by L);
// - spring −k·θa (θa the axis-angle of q) and damping −c·ω, local frame;
// - semi-implicit step with the spring and damping taken implicitly, which
//   is stable for any stiffness:
//     ω ← (ω + dt/I·(τ − k·θa)) / (1 + dt·c/I + dt²·k/I),  q ← q·exp(ω·dt)
//   (q renormalised once a frame, endJointFrame);
// - no twist: the component of ω along the segment is dropped.
// A frame's sub-steps all see the poses at entry, so what does not change
// between them is computed once per joint (prepareJointStep), the wind
// included (sampled at the frame's ends, interpolated in time), and the
// torque is evaluated in the joint's local frame (fewer rotations per step).
// Instance scale s scales lengths by s, masses by s³, inertia by s⁵,
// stiffness by s³ (r⁴/l), damping by s⁴ and areas by s².
#ifndef PLANTFIELD_SHADERS_JOINT_PHYSICS_H
#define PLANTFIELD_SHADERS_JOINT_PHYSICS_H

#include "physics_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using glm::atan;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::length;
using glm::max;
using glm::normalize;
using glm::sin;
using glm::sqrt;
#define JOINT_PHYSICS_FN inline
#else
#define JOINT_PHYSICS_FN
#endif

// A skeleton nobody follows (a free near-plant skeleton) has scale 0 and is
// neither stepped nor posed.
JOINT_PHYSICS_FN bool skeletonInUse(Skeleton sk) { return sk.scale.x > 0.0f; }

// Quaternions are vec4 (x, y, z, w).
JOINT_PHYSICS_FN vec4 quatMultiply(vec4 a, vec4 b) {
    vec3 av = vec3(a.x, a.y, a.z), bv = vec3(b.x, b.y, b.z);
    vec3 v = a.w * bv + b.w * av + cross(av, bv);
    return vec4(v.x, v.y, v.z, a.w * b.w - dot(av, bv));
}

JOINT_PHYSICS_FN vec4 quatConjugate(vec4 q) { return vec4(-q.x, -q.y, -q.z, q.w); }

JOINT_PHYSICS_FN vec3 quatRotate(vec4 q, vec3 v) {
    vec3 u = vec3(q.x, q.y, q.z);
    return v + 2.0f * cross(u, cross(u, v) + q.w * v);
}

// exp of a rotation vector (axis · angle) as a unit quaternion, from the
// series of sin(a/2)/a and cos(a/2) in a², with no branch (a CPU rasteriser
// runs both sides of one for a SIMD batch, and this runs every sub-step).
// The first terms left out, a⁸/185794560 and a¹⁰/3715891200, keep the turn
// exact to float precision up to a = 1 rad (a sub-step turns by ω·dt, far
// below that) and within 1e-4 of it up to π; past π (ω above ~1500 rad/s at
// dt = 1/480 s, a simulation already blowing up) the result is still a
// finite rotation, never a NaN. endJointFrame renormalises the product.
JOINT_PHYSICS_FN vec4 quatFromRotationVector(vec3 r) {
    float a2 = dot(r, r);
    vec3 v = r * (0.5f - a2 * (1.0f / 48.0f - a2 * (1.0f / 3840.0f - a2 * (1.0f / 645120.0f))));
    float w = 1.0f - a2 * (0.125f - a2 * (1.0f / 384.0f - a2 * (1.0f / 46080.0f - a2 * (1.0f / 10321920.0f))));
    return vec4(v.x, v.y, v.z, w);
}

// log: the rotation vector (axis · angle, angle in [0, π]) of a unit
// quaternion, with no branch and no atan (both cost the physics pass a
// third of its time on lavapipe). With h the half angle, s = sin h = |xyz|
// and d = 1 + cos h, t = s/d = tan(h/2) lies in [0, 1] and the angle is
// 4·atan t. atan by one range reduction, atan t = π/4 + atan x with
// x = (t − 1)/(t + 1) = (s − d)/(s + d) above tan(π/8), and the odd series
// of atan x / x to x¹⁴ on |x| ≤ tan(π/8), whose first term left out is
// below 2e-8. The result is xyz · angle / s, which is 4·(atan t / t)/d
// unreduced (no division by zero at the identity) and 4·(π/4 + atan x)/s
// reduced (s ≥ 0.38 there): two divisions in all.
JOINT_PHYSICS_FN vec3 rotationVectorOf(vec4 q) {
    q = q.w < 0.0f ? -q : q; // the shorter way round
    vec3 u = vec3(q.x, q.y, q.z);
    float s = length(u);
    float d = 1.0f + q.w;
    bool reduced = s > 0.41421356f * d;
    float x = (reduced ? s - d : s) / (reduced ? s + d : d);
    float x2 = x * x;
    float atanOverX =
        1.0f +
        x2 * (-1.0f / 3.0f +
              x2 * (1.0f / 5.0f +
                    x2 * (-1.0f / 7.0f +
                          x2 * (1.0f / 9.0f + x2 * (-1.0f / 11.0f + x2 * (1.0f / 13.0f - x2 * (1.0f / 15.0f)))))));
    float factor = (reduced ? 0.78539816f + x * atanOverX : atanOverX) / (reduced ? s : d);
    return u * (4.0f * factor);
}

// Yaw about +y by the plant's rotation (field_common.glsl yawMatrix), given
// as (cos, sin) of the angle; (cos, −sin) turns back.
JOINT_PHYSICS_FN vec3 yawRotate(vec2 cs, vec3 v) {
    return vec3(cs.x * v.x + cs.y * v.z, v.y, -cs.y * v.x + cs.x * v.z);
}

// The wind at a world position and time: the mean wind, gust fronts that
// travel with it (a raised sine along the wind direction, one wavelength
// apart), and turbulence of a few incommensurate sines.
JOINT_PHYSICS_FN vec3 windAt(vec3 p, float t, PhysicsUniforms u) {
    vec3 mean = vec3(u.wind.x, 0.0f, u.wind.z);
    float speed = length(mean);
    if (speed <= 0.0f) return vec3(0.0f);
    vec3 along = mean / speed;
    float front = (dot(p, along) - u.wind.w * t) / u.windDetail.y;
    float wave = 0.5f + 0.5f * sin(6.2831853f * front);
    float gust = u.wind.y * wave * wave;
    vec3 turbulence = vec3(sin(1.7f * p.x + 2.3f * t + 1.3f * sin(0.61f * p.z + 1.1f * t)),
                           0.3f * sin(2.9f * p.y + 3.1f * t + 0.7f * p.x),
                           sin(1.3f * p.z + 1.9f * t + 1.7f * sin(0.53f * p.x + 0.9f * t)));
    return mean * (1.0f + gust) + turbulence * (u.windDetail.x * speed);
}

// What a joint's sub-steps of one frame share: its parent's pose at entry
// and its own base do not change between them, nor do its scaled constants.
// The wind is sampled per frame, not per sub-step: at the centre of pressure
// where it is at entry, at the times the frame starts and ends, and
// interpolated linearly in time for each sub-step. Within a frame (1/60 s)
// the point moves millimetres and the wind's fastest sine turns by 0.05 rad,
// so this changes the force by well under a percent, and the sub-steps are
// left without any of windAt's seven sines.
struct JointStep {
    vec4 restFrame;        // Dp·R: the joint's frame is restFrame·q
    vec3 wind;             // wind at the frame's start, plant space after yaw is undone (m/s)
    vec3 windChange;       // added per sub-step: (wind at the frame's end − wind) / sub-steps (m/s)
    float arm;             // base to centre of pressure, after scale (m, local +Y)
    vec3 centreOfMass;     // of the subtree, rest local frame, after scale (m)
    vec3 weight;           // subtree mass × gravity (N, plant space: yaw leaves it unchanged)
    float dragFactor;      // ½·ρ·CdA (kg/m)
    float stiffness;       // k after scale
    float stepOverInertia; // dt/I
    float implicitScale;   // 1/(1 + dt·c/I + dt²·k/I)
};

// `parentRotation`: the parent's pose rotation at the start of the frame
// (identity for roots); `base`: the joint's base now, plant space before
// scale (its own pose applied to restBase); `entry`: the joint's state at the
// start of the frame; dt the sub-step. The frame's u.counts.z sub-steps start
// at time u.windDetail.z.
JOINT_PHYSICS_FN JointStep prepareJointStep(JointParams jp, vec4 parentRotation, vec3 base, JointState entry,
                                            Skeleton sk, PhysicsUniforms u, float dt) {
    float scale = sk.scale.x;
    float s2 = scale * scale, s3 = s2 * scale;
    float inertia = jp.dynamics.y * s3 * s2;
    float stiffness = jp.dynamics.z * s3;
    float damping = jp.dynamics.w * s2 * s2;
    JointStep c;
    c.restFrame = quatMultiply(parentRotation, jp.restRotation);
    c.arm = jp.aero.y * scale;
    c.centreOfMass = vec3(jp.load.x, jp.load.y, jp.load.z) * scale;
    c.weight = (jp.load.w * s3) * vec3(u.gravity.x, u.gravity.y, u.gravity.z);
    c.dragFactor = 0.5f * u.gravity.w * jp.aero.x * s2;
    c.stiffness = stiffness;
    c.stepOverInertia = dt / inertia;
    c.implicitScale = 1.0f / (1.0f + dt * damping / inertia + dt * dt * stiffness / inertia);

    vec2 yaw = vec2(cos(sk.placement.w), sin(sk.placement.w));
    vec2 unyaw = vec2(yaw.x, -yaw.y);
    vec3 pressure = base * scale + quatRotate(quatMultiply(c.restFrame, entry.rotation), vec3(0.0f, c.arm, 0.0f));
    vec3 worldPoint = vec3(sk.placement.x, sk.placement.y, sk.placement.z) + yawRotate(yaw, pressure);
    float steps = float(u.counts.z);
    vec3 start = yawRotate(unyaw, windAt(worldPoint, u.windDetail.z, u));
    vec3 end = yawRotate(unyaw, windAt(worldPoint, u.windDetail.z + steps * dt, u));
    c.wind = start;
    c.windChange = steps > 0.0f ? (end - start) / steps : vec3(0.0f);
    return c;
}

// Sub-step `step` (0 the first) of one joint's frame. The torque about the
// base is taken in the joint's local frame L (where the arm is (0, arm, 0)):
// the wind and the weight are turned into it, and the point's velocity there
// is ω × arm.
JOINT_PHYSICS_FN JointState stepJoint(JointStep c, JointState s, uint step, float dt) {
    vec4 toLocal = quatConjugate(quatMultiply(c.restFrame, s.rotation));
    vec3 omega = vec3(s.angularVelocity.x, s.angularVelocity.y, s.angularVelocity.z);

    vec3 armLocal = vec3(0.0f, c.arm, 0.0f);
    vec3 wind = c.wind + float(step) * c.windChange;
    vec3 relative = quatRotate(toLocal, wind) - cross(omega, armLocal);
    vec3 drag = (c.dragFactor * length(relative)) * relative;
    vec3 localTorque = cross(armLocal, drag) + cross(c.centreOfMass, quatRotate(toLocal, c.weight));

    vec3 spring = c.stiffness * rotationVectorOf(s.rotation);
    omega = (omega + c.stepOverInertia * (localTorque - spring)) * c.implicitScale;
    omega.y = 0.0f; // segments bend, they do not twist

    JointState next;
    next.rotation = quatMultiply(s.rotation, quatFromRotationVector(omega * dt));
    next.angularVelocity = vec4(omega.x, omega.y, omega.z, 0.0f);
    return next;
}

// After a frame's sub-steps. Each sub-step's turn is a unit quaternion to
// float precision (quatFromRotationVector), so the rotation drifts from
// unit length by about 1e-7 a sub-step, which rotationVectorOf tolerates;
// it is renormalised once a frame instead of every sub-step.
JOINT_PHYSICS_FN JointState endJointFrame(JointState s) {
    s.rotation = normalize(s.rotation);
    return s;
}

// The joint's rotation about its own base in rest plant space: R·q·R⁻¹.
JOINT_PHYSICS_FN vec4 jointLocalRotation(JointParams jp, JointState s) {
    return quatMultiply(jp.restRotation, quatMultiply(s.rotation, quatConjugate(jp.restRotation)));
}

// The pose of joint j composes the maps x ↦ o + M·(x − o) of j and of each
// ancestor (o its rest base, M its jointLocalRotation), the root's applied
// last. The pose pass goes level by level from the roots, so the parent's
// pose is there when its children are composed:
//   poses[j] = composeWithParent(parent of j's pose, or identity for a root, params[j], states[j]).
// At rest every M is the identity, so every pose is the identity map.
JOINT_PHYSICS_FN JointPose jointLocalMap(JointParams jp, JointState s) {
    vec4 m = jointLocalRotation(jp, s);
    vec3 o = vec3(jp.restBase.x, jp.restBase.y, jp.restBase.z);
    vec3 t = o - quatRotate(m, o);
    JointPose p;
    p.rotation = m;
    p.translation = vec4(t.x, t.y, t.z, 0.0f);
    return p;
}

// The parent's pose applied after the joint's own local map: parent ∘ local.
JOINT_PHYSICS_FN JointPose composeWithParent(JointPose parent, JointParams jp, JointState s) {
    JointPose local = jointLocalMap(jp, s);
    vec3 t = quatRotate(parent.rotation, vec3(local.translation.x, local.translation.y, local.translation.z)) +
             vec3(parent.translation.x, parent.translation.y, parent.translation.z);
    JointPose p;
    p.rotation = quatMultiply(parent.rotation, local.rotation);
    p.translation = vec4(t.x, t.y, t.z, 0.0f);
    return p;
}

// Where a pose puts a rest point (the vertex shaders' skinning).
JOINT_PHYSICS_FN vec3 posePoint(JointPose p, vec3 x) {
    return quatRotate(p.rotation, x) + vec3(p.translation.x, p.translation.y, p.translation.z);
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef JOINT_PHYSICS_FN
#endif
