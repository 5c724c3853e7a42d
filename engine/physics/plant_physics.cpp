// The CPU reference of the physics and pose passes (docs/PHYSICS.md). The
// per-joint math is shaders/shared/joint_physics.h, shared with the GPU; this file
// only builds its inputs and loops over joints.
#include "engine/physics/plant_physics.h"

#include "shaders/shared/joint_physics.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {
namespace {

const gpu::vec4 kIdentityRotation(0.0f, 0.0f, 0.0f, 1.0f);

glm::vec3 xyz(const gpu::vec4& v) { return {v.x, v.y, v.z}; }

} // namespace

uint32_t addSkeleton(SkeletonSet& set, uint32_t model, uint32_t firstParam, uint32_t joints, const glm::vec3& position,
                     float yaw, float scale) {
    const uint32_t index = uint32_t(set.skeletons.size());
    const uint32_t firstState = uint32_t(set.states.size());
    gpu::Skeleton skeleton;
    skeleton.ids = gpu::uvec4(model, firstParam, joints, firstState);
    skeleton.placement = gpu::vec4(position, yaw);
    skeleton.scale = gpu::vec4(scale, 0.0f, 0.0f, 0.0f);
    set.skeletons.push_back(skeleton);
    set.states.insert(set.states.end(), joints, gpu::JointState{kIdentityRotation, gpu::vec4(0.0f)});
    set.poses.insert(set.poses.end(), joints, gpu::JointPose{kIdentityRotation, gpu::vec4(0.0f)});
    set.jointSkeleton.insert(set.jointSkeleton.end(), joints, index);
    return index;
}

gpu::PhysicsUniforms makePhysicsUniforms(const Wind& wind, const PhysicsSettings& settings, float time, float dt,
                                         uint32_t subSteps, uint32_t skeletons, uint32_t joints) {
    const glm::vec3 velocity = meanWindVelocity(wind);
    gpu::PhysicsUniforms u;
    u.gravity = gpu::vec4(0.0f, -settings.gravity, 0.0f, settings.airDensity);
    u.wind = gpu::vec4(velocity.x, wind.gustStrength, velocity.z, wind.gustSpeed);
    u.windDetail = gpu::vec4(wind.turbulence, kGustWavelength, time, dt);
    u.counts = gpu::uvec4(skeletons, joints, subSteps, 0);
    return u;
}

void stepSkeletonsOnCpu(SkeletonSet& set, const gpu::PhysicsUniforms& u) {
    const std::vector<gpu::JointPose> entry = set.poses; // every joint sees the poses of the start
    for (size_t i = 0; i < set.states.size(); ++i) {
        const gpu::Skeleton& skeleton = set.skeletons[set.jointSkeleton[i]];
        if (!gpu::skeletonInUse(skeleton)) continue;
        const uint32_t joint = uint32_t(i) - skeleton.ids.w;
        const gpu::JointParams& p = set.params[skeleton.ids.y + joint];
        const uint32_t parent = p.links.x;
        const gpu::vec4 parentRotation =
            parent == JOINT_NO_PARENT ? kIdentityRotation : entry[skeleton.ids.w + parent].rotation;
        const glm::vec3 base = gpu::posePoint(entry[i], xyz(p.restBase));
        const float dt = u.windDetail.w;
        gpu::JointState state = set.states[i];
        const gpu::JointStep c = gpu::prepareJointStep(p, parentRotation, base, state, skeleton, u, dt);
        for (uint32_t step = 0; step < u.counts.z; ++step) state = gpu::stepJoint(c, state, step, dt);
        set.states[i] = gpu::endJointFrame(state);
    }
}

void poseSkeletonsOnCpu(SkeletonSet& set) {
    // Like the GPU's pose levels: every joint after its parent (a counting
    // sort by depth), each composed onto its parent's new pose.
    const size_t n = set.states.size();
    auto paramsOf = [&](size_t i) -> const gpu::JointParams& {
        const gpu::Skeleton& skeleton = set.skeletons[set.jointSkeleton[i]];
        return set.params[skeleton.ids.y + (uint32_t(i) - skeleton.ids.w)];
    };
    std::vector<uint32_t> start;
    for (size_t i = 0; i < n; ++i) {
        const uint32_t depth = paramsOf(i).links.y;
        if (depth + 2 > start.size()) start.resize(depth + 2, 0);
        ++start[depth + 1];
    }
    for (size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    std::vector<uint32_t> order(n);
    for (size_t i = 0; i < n; ++i) order[start[paramsOf(i).links.y]++] = uint32_t(i);

    const gpu::JointPose identity{kIdentityRotation, gpu::vec4(0.0f)};
    for (const uint32_t i : order) {
        const gpu::Skeleton& skeleton = set.skeletons[set.jointSkeleton[i]];
        if (!gpu::skeletonInUse(skeleton)) continue;
        const gpu::JointParams& p = paramsOf(i);
        const uint32_t firstState = skeleton.ids.w;
        const gpu::JointPose parent = p.links.x == JOINT_NO_PARENT ? identity : set.poses[firstState + p.links.x];
        set.poses[i] = gpu::composeWithParent(parent, p, set.states[i]);
    }
}

uint32_t subStepsBetween(double a, double b, const PhysicsSettings& settings) {
    return uint32_t(subStepsUntil(b, settings) - subStepsUntil(a, settings));
}

uint64_t subStepsUntil(double t, const PhysicsSettings& settings) {
    // A float sub-step of 1/n s (n whole) is not exactly 1/n: count in steps of exactly 1/n.
    const double stepsPerSecond = 1.0 / double(settings.subStep);
    const double whole = std::round(stepsPerSecond);
    const double rate = std::abs(stepsPerSecond - whole) <= 1e-6 * whole ? whole : stepsPerSecond;
    return uint64_t(std::max(0.0, std::floor(t * rate + kSubStepRoundingSlack)));
}

} // namespace pf
