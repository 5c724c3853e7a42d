// The physical model of a plant's skeleton, built from its L-system with
// the plant models (docs/PHYSICS.md): masses, inertias, stiffnesses, drag.
#include "engine/scene/joint_params.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {
namespace {

// Floors that keep a degenerate joint (zero length or radius) finite: it
// weighs at least a milligram with the inertia of a millimetre rod of that
// mass, so 1/I stays finite and an implicit step of it stays well defined.
// Real joints are orders of magnitude above both.
constexpr float kMinMass = 1e-6f;                   // kg
constexpr float kMinInertia = 1e-6f * 1e-6f / 3.0f; // kg·m², kMinMass on a 1 mm rod
// Beam theory divides by the length; a zero-length joint is as stiff as a 1 mm one.
constexpr float kMinBeamLength = 1e-3f; // m
// Fresh leaves weigh 0.1–0.3 kg/m². Their weight loads the joint and their
// inertia keeps the explicit drag of a leafy twig stable (docs/PHYSICS.md).
constexpr float kLeafMassPerArea = 0.2f; // kg/m²

gpu::vec4 asVec4(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

// Segment direction (local +Y) of a frame, in plant space.
glm::vec3 headingOf(const lsys::Frame& frame) { return frame.rotation * glm::vec3(0.0f, 1.0f, 0.0f); }

// Drag sources attached to a joint: an area (m², already weighted by Cd or
// leafDrag) acting at a distance along the segment from its base.
struct DragSum {
    float area = 0.0f;
    float areaTimesDistance = 0.0f;
    void add(float a, float distance) {
        area += a;
        areaTimesDistance += a * distance;
    }
};

// A leaf card as plant_models bakes it: the surface's local x-y extent
// scaled uniformly by the primitive's length. Returns area and centre (plant space, unscaled).
struct Card {
    float area = 0.0f;
    glm::vec3 centre{0.0f};
};

Card leafCard(const lsys::PlantAsset& asset, const lsys::Primitive& surface) {
    const lsys::SurfaceMesh& mesh = asset.surfaces.at(surface.shape);
    if (mesh.positions.empty()) return {0.0f, surface.frame.position};
    glm::vec2 lo(mesh.positions.front()), hi(mesh.positions.front());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, glm::vec2(p));
        hi = glm::max(hi, glm::vec2(p));
    }
    const float s = surface.length;
    const glm::vec3 centreLocal(0.5f * (lo + hi), 0.0f);
    return {std::abs(s * s * (hi.x - lo.x) * (hi.y - lo.y)),
            surface.frame.position + surface.frame.rotation * (s * centreLocal)};
}

// A `{ … }` polygon: its outline's area (Newell) and mean vertex, plant space.
Card polygonCard(const lsys::PlantAsset& asset, const lsys::Primitive& polygon) {
    const std::vector<glm::vec3>& outline = asset.polygons.at(polygon.shape).outline;
    if (outline.empty()) return {0.0f, polygon.frame.position};
    glm::vec3 twiceArea(0.0f), sum(0.0f);
    for (size_t i = 0; i < outline.size(); ++i) {
        twiceArea += glm::cross(outline[i], outline[(i + 1) % outline.size()]);
        sum += outline[i];
    }
    return {0.5f * glm::length(twiceArea), sum / float(outline.size())};
}

// Depth of every joint (roots 0), following parents; parents need not come first.
std::vector<uint32_t> jointDepths(const std::vector<lsys::Joint>& joints) {
    std::vector<uint32_t> depth(joints.size(), 0);
    std::vector<bool> known(joints.size(), false);
    std::vector<size_t> path;
    for (size_t j = 0; j < joints.size(); ++j) {
        size_t k = j;
        while (!known[k] && joints[k].parent >= 0) {
            path.push_back(k);
            k = size_t(joints[k].parent);
        }
        uint32_t d = known[k] ? depth[k] : 0;
        known[k] = true;
        while (!path.empty()) {
            depth[path.back()] = ++d;
            known[path.back()] = true;
            path.pop_back();
        }
    }
    return depth;
}

} // namespace

std::vector<gpu::JointParams> buildJointParams(const lsys::PlantAsset& asset, float scale,
                                               const PhysicsSettings& settings) {
    const size_t count = asset.joints.size();
    std::vector<gpu::JointParams> params(count);
    if (count == 0) return params;

    // Which joints are blades: the segment primitive of the joint has a two-sided material.
    std::vector<bool> blade(count, false);
    for (const lsys::Primitive& p : asset.primitives)
        if (p.kind == lsys::PrimitiveKind::Segment && p.joint >= 0 && size_t(p.joint) < count)
            blade[size_t(p.joint)] = p.material < asset.materials.size() && asset.materials[p.material].twoSided;

    // What each joint carries, as point masses in rest plant space (scaled):
    // Σm, Σm·x and Σ(m·|x|² + own inertia about its centre), summed over
    // subtrees below, in double so the inertia's shift to a far base keeps its digits.
    struct Masses {
        double mass = 0.0;
        glm::dvec3 moment{0.0};
        double second = 0.0;
        void add(double m, const glm::dvec3& x, double ownInertia) {
            mass += m;
            moment += m * x;
            second += m * glm::dot(x, x) + ownInertia;
        }
        void add(const Masses& other) {
            mass += other.mass;
            moment += other.moment;
            second += other.second;
        }
    };
    std::vector<Masses> carried(count);
    std::vector<DragSum> drag(count);
    std::vector<glm::vec3> base(count), heading(count);
    std::vector<float> length(count);
    for (size_t j = 0; j < count; ++j) {
        const lsys::Joint& joint = asset.joints[j];
        length[j] = joint.length * scale;
        const float radius = 0.5f * (joint.startRadius + joint.endRadius) * scale;
        const float baseRadius = joint.startRadius * scale;
        base[j] = joint.rest.position * scale;
        heading[j] = headingOf(joint.rest);
        // Blades (needle sprays, grass) are foliage, not wood: a sheet's
        // mass per area, not a solid cylinder's volume.
        const float volumeMass = settings.woodDensity * std::numbers::pi_v<float> * radius * radius * length[j];
        const float sheetMass = kLeafMassPerArea * 2.0f * radius * length[j];
        const float mass = std::max(blade[j] ? sheetMass : volumeMass, kMinMass);
        // A rod about its centre; its mass at its midpoint (m·l²/12 + m·(l/2)² = m·l²/3 about the base).
        carried[j].add(mass, glm::dvec3(base[j] + 0.5f * length[j] * heading[j]),
                       double(mass) * length[j] * length[j] / 12.0);

        // @K is a physical stiffness already (N·m/rad): the height scale does not change it.
        const float beam = settings.youngsModulus * std::numbers::pi_v<float> * std::pow(baseRadius, 4.0f) /
                           (4.0f * std::max(length[j], kMinBeamLength));
        gpu::JointParams& p = params[j];
        p.restBase = gpu::vec4(base[j], length[j]);
        p.restRotation = asVec4(joint.rest.rotation);
        p.dynamics =
            gpu::vec4(mass, 0.0f, (joint.stiffness > 0.0f ? joint.stiffness : beam) * settings.stiffnessScale, 0.0f);
        p.links = gpu::uvec4(joint.parent >= 0 ? uint32_t(joint.parent) : JOINT_NO_PARENT, 0, 0, 0);

        const float segmentArea = 2.0f * radius * length[j];
        drag[j].add(segmentArea * (blade[j] ? settings.leafDrag : settings.dragCoefficient), 0.5f * length[j]);
    }

    // Leaves and polygons add drag where they are, projected on their joint's
    // axis, and their weight. A primitive on the plant's base (joint -1)
    // moves with joint 0, as plant_models bakes it.
    for (const lsys::Primitive& p : asset.primitives) {
        Card card;
        if (p.kind == lsys::PrimitiveKind::Surface)
            card = leafCard(asset, p);
        else if (p.kind == lsys::PrimitiveKind::Polygon)
            card = polygonCard(asset, p);
        else
            continue;
        const size_t j = p.joint < 0 ? 0 : size_t(p.joint);
        if (j >= count) continue;
        const float area = card.area * scale * scale;
        const glm::vec3 centre = card.centre * scale;
        drag[j].add(area * settings.leafDrag, std::clamp(glm::dot(centre - base[j], heading[j]), 0.0f, length[j]));
        carried[j].add(kLeafMassPerArea * area, glm::dvec3(centre), 0.0);
    }

    // Subtrees, deepest joints first so every child is summed before its parent.
    const std::vector<uint32_t> depth = jointDepths(asset.joints);
    std::vector<size_t> order(count);
    for (size_t j = 0; j < count; ++j) order[j] = j;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return depth[a] > depth[b]; });
    for (size_t j : order)
        if (asset.joints[j].parent >= 0) carried[size_t(asset.joints[j].parent)].add(carried[j]);

    for (size_t j = 0; j < count; ++j) {
        gpu::JointParams& p = params[j];
        const Masses& m = carried[j];
        const glm::dvec3 o(base[j]);
        const glm::dvec3 centre = m.moment / m.mass - o;
        // Σm·|x − o|² + Σ own = second − 2·o·moment + |o|²·mass: the subtree turning rigidly about the base.
        const double inertia = m.second - 2.0 * glm::dot(o, m.moment) + glm::dot(o, o) * m.mass;
        p.dynamics.y = std::max(float(inertia), kMinInertia);
        p.dynamics.w = 2.0f * settings.dampingRatio * std::sqrt(p.dynamics.z * p.dynamics.y);
        p.load = gpu::vec4(glm::inverse(asset.joints[j].rest.rotation) * glm::vec3(centre), float(m.mass));
        p.aero =
            gpu::vec4(drag[j].area, drag[j].area > 0.0f ? drag[j].areaTimesDistance / drag[j].area : 0.5f * length[j],
                      0.0f, 0.0f);
        p.links.y = depth[j];
    }
    return params;
}

} // namespace pf
