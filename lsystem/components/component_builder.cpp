// buildComponentPlant: Tankard 2001's Render chain (§4.1.2.1, §4.1.3). Each
// component draws itself at a placement and then its children at theirs;
// what it draws goes into a PlantAsset through PlantAssetBuilder, as the
// turtle's drawing does, so component plants meet the same renderer, skeleton
// and exporters as L-system plants.
#include "lsystem/components/component_graph.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "lsystem/common/random.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys::components {
namespace {

constexpr glm::vec3 kHeading{0.0f, 1.0f, 0.0f};
// Local X (the turtle's −L): a branch tilts about it, as the turtle's & and ^
// pitch, so a blade in its frame's XY plane keeps facing up.
constexpr glm::vec3 kPitchAxis{1.0f, 0.0f, 0.0f};

// Where a component is drawn: its frame, its size relative to the file's
// metres, and the joint it grows on (-1: the plant's base).
struct Placement {
    Frame frame;
    float scale = 1.0f;
    int32_t joint = -1;
};

// The rotation taking unit vector a to unit vector b by the shortest arc, so
// a stem's rings follow its curve without twisting.
glm::quat shortestArc(glm::vec3 a, glm::vec3 b) {
    const float cosine = glm::dot(a, b);
    if (cosine < -0.9999f) {
        const glm::vec3 axis =
            std::abs(a.x) < 0.9f ? glm::cross(a, glm::vec3(1, 0, 0)) : glm::cross(a, glm::vec3(0, 0, 1));
        return glm::angleAxis(std::numbers::pi_v<float>, glm::normalize(axis));
    }
    const glm::vec3 axis = glm::cross(a, b);
    return glm::normalize(glm::quat(1.0f + cosine, axis.x, axis.y, axis.z));
}

// A child's rotation at a node of `frame`: turned about the axis, tilted off
// it, then twisted about its own axis (degrees) — a tree's branch and a
// radial's child alike.
glm::quat childRotation(glm::quat frame, float turn, float tilt, float twist) {
    return frame * glm::angleAxis(glm::radians(turn), kHeading) * glm::angleAxis(glm::radians(tilt), kPitchAxis) *
           glm::angleAxis(glm::radians(twist), kHeading);
}

// The drawn stem: a frame and length per segment, and the joint it moves with.
struct StemSegment {
    Frame base;
    float length = 0.0f;
    int32_t joint = -1;
};

class ComponentPlantBuilder {
public:
    explicit ComponentPlantBuilder(const ComponentGraph& graph)
        : graph_(graph),
          assets_(surfaces_, PlantLook{std::make_shared<const std::vector<Material>>(graph.materials), {}}),
          random_{splitmix64(graph.seed), 0} {}

    PlantAsset build() {
        draw(graph_.root, Placement{});
        return assets_.finish();
    }

private:
    void draw(uint32_t index, const Placement& at) {
        const Component& component = graph_.components[index];
        // Each value is bounded as read, but scales multiply down a chain of
        // components and may pass the float range: refused where it happens.
        const glm::vec3& p = at.frame.position;
        if (!std::isfinite(at.scale) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw ComponentError(component.location +
                                 " is drawn at a size or place past the float range: the scales of the components "
                                 "drawing it multiply past it");
        std::visit([&](const auto& kind) { drawKind(component, kind, at); }, component.kind);
    }

    void drawChildren(const Component& component, const Placement& at) {
        for (uint32_t child : component.children) draw(child, at);
    }

    // Tankard §4.1.2.2.1: `detail` points of the shape spline joined by
    // segments; each segment is a joint on the one before, so the stem bends
    // as a chain (and the renderer draws it as one generalised cylinder).
    std::vector<StemSegment> drawStem(const Stem& stem, const Placement& at, bool visible) {
        std::vector<StemSegment> segments;
        const float size = stem.length * at.scale;
        glm::quat rotation = at.frame.rotation;
        glm::vec3 heading = rotation * kHeading;
        int32_t joint = at.joint;
        glm::vec3 start = at.frame.position + at.frame.rotation * (splinePosition(stem.shape, 0.0f) * size);
        for (uint32_t i = 0; i < stem.detail; ++i) {
            const float u0 = float(i) / float(stem.detail), u1 = float(i + 1) / float(stem.detail);
            const glm::vec3 end = at.frame.position + at.frame.rotation * (splinePosition(stem.shape, u1) * size);
            const float length = glm::length(end - start);
            if (length > 0.0f) {
                const glm::vec3 direction = (end - start) / length;
                rotation = glm::normalize(shortestArc(heading, direction) * rotation);
                heading = direction;
            }
            const Frame base{start, rotation};
            if (visible) {
                const float r0 = std::max(0.0f, valueAt(stem.radius, u0)) * at.scale;
                const float r1 = std::max(0.0f, valueAt(stem.radius, u1)) * at.scale;
                joint = assets_.addSegment(base, length, r0, r1, stem.material, joint, stem.stiffness);
            }
            segments.push_back({base, length, joint});
            start = end;
        }
        return segments;
    }

    // The frame and joint at fractional distance u along a drawn stem.
    static Placement along(const std::vector<StemSegment>& segments, float u, float scale) {
        const float scaled = std::clamp(u, 0.0f, 1.0f) * float(segments.size());
        const size_t index = std::min(size_t(scaled), segments.size() - 1);
        const StemSegment& segment = segments[index];
        const glm::vec3 position =
            segment.base.position + segment.base.rotation * kHeading * (segment.length * (scaled - float(index)));
        return {{position, segment.base.rotation}, scale, segment.joint};
    }

    void drawKind(const Component& component, const Stem& stem, const Placement& at) {
        const std::vector<StemSegment> segments = drawStem(stem, at, true);
        drawChildren(component, along(segments, 1.0f, at.scale));
    }

    // Tankard §4.1.2.2.2: the half outline sampled at `detail` points and
    // mirrored about x = 0 into one polygon in the frame's XY plane.
    void drawKind(const Component&, const Leaf& leaf, const Placement& at) {
        std::vector<glm::vec3> blade = leaf.polygon;
        if (blade.empty()) {
            std::vector<glm::vec3> half;
            for (uint32_t j = 0; j < leaf.detail; ++j)
                half.push_back(splinePosition(leaf.halfOutline, float(j) / float(leaf.detail - 1)));
            blade = half;
            for (auto it = half.rbegin(); it != half.rend(); ++it)
                if (std::abs(it->x) > 1e-6f) blade.push_back({-it->x, it->y, 0.0f}); // the midrib's points once
        }
        const float fold = glm::radians(leaf.fold), size = leaf.length * at.scale;
        std::vector<glm::vec3> outline;
        for (const glm::vec3& p : blade) {
            const glm::vec3 folded{p.x * std::cos(fold), p.y, std::abs(p.x) * std::sin(fold)};
            outline.push_back(at.frame.position + at.frame.rotation * (folded * size));
        }
        assets_.addPolygon(at.frame, std::move(outline), leaf.material, at.joint);
    }

    // Tankard §4.1.2.3.1: `count` nodes evenly along the stem, turned by the
    // phyllotaxis about it and tilted by the branching angle, scaled by the
    // branch-scale spline. Variation as §4.1.2.3.1.4, except that the scale
    // varies both ways: s(1 + v(1 − 2r)), where the thesis's s − 2rvs only shrinks.
    void drawKind(const Component& component, const Tree& tree, const Placement& at) {
        const Component& stemComponent = graph_.components[tree.stem];
        const Stem& stem = std::get<Stem>(stemComponent.kind);
        // A hidden stem draws nothing but still carries its children
        // (Lintermann and Deussen's hidden components; Tankard's stemVisible).
        const std::vector<StemSegment> segments = drawStem(stem, at, tree.stemVisible);
        Placement tip = along(segments, 1.0f, at.scale);
        if (!tree.stemVisible) tip.joint = at.joint;
        drawChildren(stemComponent, tip);
        float azimuth = tree.azimuth;
        for (uint32_t k = 0; k < tree.count; ++k) {
            const float u =
                tree.count == 1 ? tree.start : tree.start + (tree.end - tree.start) * float(k) / float(tree.count - 1);
            if (k > 0) azimuth += valueAt(tree.phyllotaxis, u);
            const float angle = valueAt(tree.angle, u) + tree.angleVariation * variation();
            const float scale =
                at.scale * std::max(0.0f, valueAt(tree.scale, u)) * (1.0f + tree.scaleVariation * variation());
            Placement node = along(segments, u, scale);
            if (!tree.stemVisible) node.joint = at.joint;
            node.frame.rotation = childRotation(node.frame.rotation, azimuth, angle, tree.twist);
            drawChildren(component, node);
        }
    }

    // Tankard §4.1.2.3.2: children around the node, interChildAngle apart
    // about its axis, nodeAngle off it, each twisted nodeTwist about its own.
    void drawKind(const Component& component, const Radial& radial, const Placement& at) {
        for (uint32_t i = 0; i < radial.count; ++i) {
            const float turn = radial.interChildAngle * float(i) + radial.angleVariation * variation();
            const float elevation = radial.nodeAngle + radial.angleVariation * variation();
            Placement node = at;
            node.frame.rotation = childRotation(at.frame.rotation, turn, elevation, radial.nodeTwist);
            drawChildren(component, node);
        }
    }

    // Uniform in [-1, 1): the thesis's (1 − 2r), drawn in the order the
    // graph is drawn, so a seed gives one plant.
    float variation() { return float(1.0 - 2.0 * random_.uniform()); }

    const ComponentGraph& graph_;
    SurfaceLibrary surfaces_; // none: components draw no predefined surfaces
    PlantAssetBuilder assets_;
    RandomStream random_;
};

} // namespace

PlantAsset buildComponentPlant(const ComponentGraph& graph, const MemoryBudget& memory) {
    requireWithinBudgets(graph, countComponentPlant(graph), memory);
    return ComponentPlantBuilder(graph).build();
}

} // namespace lsys::components
