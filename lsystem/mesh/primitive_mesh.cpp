#include "lsystem/mesh/primitive_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include "lsystem/common/memory_budget.h"

namespace lsys {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

glm::vec3 heading(const Frame& frame) { return frame.rotation * glm::vec3(0.0f, 1.0f, 0.0f); }

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return length > 1e-12f ? v / length : fallback;
}

// Any unit vector perpendicular to the unit vector `axis`.
glm::vec3 perpendicular(const glm::vec3& axis) {
    const glm::vec3 other = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(other, axis));
}

// One cross-section of a tube. `x` and `z = x × axis` span its plane;
// `stretch` > 1 lengthens it along `bend` (a unit vector in the plane), which
// makes a mitre joint; `slope` tilts the normals of a cone towards its tip.
struct Ring {
    glm::vec3 centre;
    glm::vec3 axis;
    glm::vec3 x;
    float radius;
    float slope;
    float v;
    glm::vec3 bend{0.0f};
    float stretch = 1.0f;
};

void appendRing(TriangleMesh& mesh, const Ring& ring, uint32_t sides) {
    const glm::vec3 z = glm::cross(ring.x, ring.axis);
    for (uint32_t j = 0; j <= sides; ++j) {
        const float angle = kTwoPi * float(j % sides) / float(sides);
        const glm::vec3 radial = std::cos(angle) * ring.x + std::sin(angle) * z;
        glm::vec3 offset = ring.radius * radial;
        offset += ring.bend * (glm::dot(offset, ring.bend) * (ring.stretch - 1.0f));
        mesh.positions.push_back(ring.centre + offset);
        mesh.normals.push_back(glm::normalize(radial + ring.slope * ring.axis));
        mesh.uvs.push_back({float(j) / float(sides), ring.v});
    }
}

// A disc closing the tube at `ring`, facing along the axis at the tip
// (`facingAxis`) and against it at the base.
void appendCap(TriangleMesh& mesh, const Ring& ring, uint32_t sides, bool facingAxis) {
    const uint32_t centre = mesh.vertexCount();
    const glm::vec3 normal = facingAxis ? ring.axis : -ring.axis;
    const glm::vec3 z = glm::cross(ring.x, ring.axis);
    mesh.positions.push_back(ring.centre);
    mesh.normals.push_back(normal);
    mesh.uvs.push_back({0.5f, 0.5f});
    for (uint32_t j = 0; j < sides; ++j) {
        const float angle = kTwoPi * float(j) / float(sides);
        mesh.positions.push_back(ring.centre + ring.radius * (std::cos(angle) * ring.x + std::sin(angle) * z));
        mesh.normals.push_back(normal);
        mesh.uvs.push_back({0.5f + 0.5f * std::cos(angle), 0.5f + 0.5f * std::sin(angle)});
    }
    for (uint32_t j = 0; j < sides; ++j) {
        const uint32_t a = centre + 1 + j, b = centre + 1 + (j + 1) % sides;
        if (facingAxis)
            mesh.indices.insert(mesh.indices.end(), {centre, b, a});
        else
            mesh.indices.insert(mesh.indices.end(), {centre, a, b});
    }
}

// Rings in order along the axis, joined by quads, optionally capped.
TriangleMesh tubeMesh(const std::vector<Ring>& rings, const MeshDetail& detail) {
    const uint32_t sides = std::max(detail.segmentSides, 3u);
    TriangleMesh mesh;
    for (const Ring& ring : rings) appendRing(mesh, ring, sides);
    for (uint32_t i = 0; i + 1 < rings.size(); ++i) {
        for (uint32_t j = 0; j < sides; ++j) {
            const uint32_t below = i * (sides + 1) + j, above = below + sides + 1;
            mesh.indices.insert(mesh.indices.end(), {below, above, below + 1, below + 1, above, above + 1});
        }
    }
    if (detail.segmentCaps) {
        appendCap(mesh, rings.front(), sides, false);
        appendCap(mesh, rings.back(), sides, true);
    }
    return mesh;
}

float coneSlope(float length, float startRadius, float endRadius) {
    return length > 0.0f ? (startRadius - endRadius) / length : 0.0f;
}

// Ear clipping of a counter-clockwise simple polygon; appends n−2 triangles.
// When rounding leaves no clean ear (near-degenerate or self-touching input),
// the most convex corner is clipped so the count holds anyway.
void clipEars(const std::vector<glm::vec2>& points, std::vector<uint32_t>& indices) {
    std::vector<uint32_t> remaining(points.size());
    for (uint32_t i = 0; i < remaining.size(); ++i) remaining[i] = i;
    const auto corner = [&](size_t k) {
        const size_t n = remaining.size();
        return std::array<uint32_t, 3>{remaining[(k + n - 1) % n], remaining[k], remaining[(k + 1) % n]};
    };
    const auto cross = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
    const auto turn = [&](const std::array<uint32_t, 3>& c) {
        return cross(points[c[1]] - points[c[0]], points[c[2]] - points[c[1]]);
    };
    const auto inside = [&](glm::vec2 p, const std::array<uint32_t, 3>& c) {
        const glm::vec2 a = points[c[0]], b = points[c[1]], d = points[c[2]];
        return cross(b - a, p - a) >= 0.0f && cross(d - b, p - b) >= 0.0f && cross(a - d, p - d) >= 0.0f;
    };
    while (remaining.size() > 3) {
        size_t chosen = remaining.size();
        size_t mostConvex = 0;
        for (size_t k = 0; k < remaining.size(); ++k) {
            const auto c = corner(k);
            if (turn(c) > turn(corner(mostConvex))) mostConvex = k;
            if (turn(c) <= 0.0f) continue;
            const bool blocked = std::any_of(remaining.begin(), remaining.end(), [&](uint32_t other) {
                return other != c[0] && other != c[1] && other != c[2] && inside(points[other], c);
            });
            if (!blocked) {
                chosen = k;
                break;
            }
        }
        if (chosen == remaining.size()) chosen = mostConvex;
        const auto c = corner(chosen);
        indices.insert(indices.end(), c.begin(), c.end());
        remaining.erase(remaining.begin() + std::ptrdiff_t(chosen));
    }
    indices.insert(indices.end(), remaining.begin(), remaining.end());
}

} // namespace

void TriangleMesh::append(const TriangleMesh& mesh, const glm::mat4& transform) {
    const uint32_t base = vertexCount();
    const glm::mat3 linear(transform);
    for (const glm::vec3& p : mesh.positions) positions.push_back(glm::vec3(transform * glm::vec4(p, 1.0f)));
    for (const glm::vec3& n : mesh.normals) normals.push_back(unitOr(linear * n, n));
    uvs.insert(uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    for (uint32_t index : mesh.indices) indices.push_back(base + index);
}

TriangleMesh segmentMesh(float length, float startRadius, float endRadius, const MeshDetail& detail) {
    const glm::vec3 up(0, 1, 0), x(1, 0, 0);
    const float slope = coneSlope(length, startRadius, endRadius);
    return tubeMesh(
        {Ring{glm::vec3(0.0f), up, x, startRadius, slope, 0.0f}, Ring{length * up, up, x, endRadius, slope, length}},
        detail);
}

TriangleMesh sphereMesh(float radius, const MeshDetail& detail) {
    const uint32_t slices = std::max(detail.sphereSlices, 3u), stacks = std::max(detail.sphereStacks, 2u);
    TriangleMesh mesh;
    for (uint32_t i = 0; i <= stacks; ++i) {
        const float polar = std::numbers::pi_v<float> * float(i) / float(stacks);
        for (uint32_t j = 0; j <= slices; ++j) {
            const float azimuth = kTwoPi * float(j % slices) / float(slices);
            // The poles are exact so their rings collapse to one point.
            const float sinPolar = (i == 0 || i == stacks) ? 0.0f : std::sin(polar);
            const glm::vec3 n(sinPolar * std::cos(azimuth), std::cos(polar), sinPolar * std::sin(azimuth));
            mesh.positions.push_back(radius * n);
            mesh.normals.push_back(n);
            mesh.uvs.push_back({float(j) / float(slices), float(i) / float(stacks)});
        }
    }
    // Stack i runs from ring i (upper) to ring i+1 (lower); the pole stacks
    // have one triangle per slice because the pole's quad edge has no length.
    for (uint32_t i = 0; i < stacks; ++i) {
        for (uint32_t j = 0; j < slices; ++j) {
            const uint32_t upper = i * (slices + 1) + j, lower = upper + slices + 1;
            if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {lower, upper, lower + 1});
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {lower + 1, upper, upper + 1});
        }
    }
    return mesh;
}

TriangleMesh polygonMesh(const std::vector<glm::vec3>& outline) {
    std::vector<glm::vec3> points;
    for (const glm::vec3& p : outline)
        if (points.empty() || p != points.back()) points.push_back(p);
    while (points.size() > 1 && points.front() == points.back()) points.pop_back();
    TriangleMesh mesh;
    if (points.size() < 3) return mesh;

    // Newell's normal: twice the area vector, robust for non-planar outlines.
    glm::vec3 centre(0.0f), area(0.0f);
    for (const glm::vec3& p : points) centre += p / float(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        area += glm::cross(points[i] - centre, points[(i + 1) % points.size()] - centre);
    const float extent = glm::length(area);
    if (!(extent > 1e-12f)) return mesh;
    const glm::vec3 normal = area / extent;
    const glm::vec3 u = perpendicular(normal), v = glm::cross(normal, u);

    std::vector<glm::vec2> planar;
    for (const glm::vec3& p : points) {
        planar.push_back({glm::dot(p - centre, u), glm::dot(p - centre, v)});
        mesh.positions.push_back(p);
        mesh.normals.push_back(normal);
        mesh.uvs.push_back(planar.back());
    }
    clipEars(planar, mesh.indices);
    return mesh;
}

TriangleMesh surfaceMesh(const SurfaceMesh& surface) {
    TriangleMesh mesh{surface.positions, {}, surface.uvs, surface.indices};
    const size_t count = surface.positions.size();
    if (surface.normals.size() == count) {
        for (const glm::vec3& n : surface.normals) mesh.normals.push_back(unitOr(n, glm::vec3(0, 0, 1)));
    } else {
        // Area-weighted face normals summed at each corner.
        std::vector<glm::vec3> sums(count, glm::vec3(0.0f));
        for (size_t t = 0; t + 2 < surface.indices.size(); t += 3) {
            const uint32_t a = surface.indices[t], b = surface.indices[t + 1], c = surface.indices[t + 2];
            const glm::vec3 face =
                glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            for (uint32_t corner : {a, b, c}) sums[corner] += face;
        }
        for (const glm::vec3& n : sums) mesh.normals.push_back(unitOr(n, glm::vec3(0, 0, 1)));
    }
    if (mesh.uvs.size() != count) mesh.uvs.assign(count, glm::vec2(0.0f));
    return mesh;
}

std::vector<SegmentChain> segmentChains(const PlantAsset& asset) {
    const auto& primitives = asset.primitives;
    const auto isChainable = [&](uint32_t p) {
        const Primitive& s = primitives[p];
        return s.kind == PrimitiveKind::Segment && isDrawable(s) && s.joint >= 0 &&
               size_t(s.joint) < asset.joints.size();
    };
    std::vector<int64_t> segmentOfJoint(asset.joints.size(), -1);
    for (uint32_t p = 0; p < primitives.size(); ++p)
        if (isChainable(p)) segmentOfJoint[size_t(primitives[p].joint)] = p;

    // next[p]: the segment continuing p; best[p]: how straight it goes on.
    std::vector<int64_t> next(primitives.size(), -1);
    std::vector<float> best(primitives.size(), 0.0f);
    std::vector<bool> continues(primitives.size(), false);
    for (uint32_t p = 0; p < primitives.size(); ++p) {
        if (!isChainable(p)) continue;
        const int32_t parentJoint = asset.joints[size_t(primitives[p].joint)].parent;
        if (parentJoint < 0 || size_t(parentJoint) >= asset.joints.size() || segmentOfJoint[size_t(parentJoint)] < 0)
            continue;
        const auto q = uint32_t(segmentOfJoint[size_t(parentJoint)]);
        const Primitive& parent = primitives[q];
        const Primitive& child = primitives[p];
        const glm::vec3 tip = parent.frame.position + parent.length * heading(parent.frame);
        const float tolerance = 1e-4f * std::max(1.0f, parent.length);
        const float straightness = glm::dot(heading(parent.frame), heading(child.frame));
        if (child.material != parent.material || glm::length(child.frame.position - tip) > tolerance ||
            straightness <= best[q])
            continue;
        next[q] = p;
        best[q] = straightness;
    }
    for (int64_t p : next)
        if (p >= 0) continues[size_t(p)] = true;

    std::vector<SegmentChain> chains;
    for (uint32_t p = 0; p < primitives.size(); ++p) {
        if (primitives[p].kind != PrimitiveKind::Segment || !isDrawable(primitives[p]) || continues[p]) continue;
        SegmentChain& chain = chains.emplace_back();
        for (int64_t s = p; s >= 0; s = next[size_t(s)]) chain.primitives.push_back(uint32_t(s));
    }
    return chains;
}

TriangleMesh generalizedCylinderMesh(const PlantAsset& asset, const SegmentChain& chain, const MeshDetail& detail) {
    if (chain.primitives.empty()) return {};
    std::vector<const Primitive*> segments;
    for (uint32_t p : chain.primitives) segments.push_back(&asset.primitives[p]);

    const Primitive& first = *segments.front();
    const float firstSlope = coneSlope(first.length, first.startRadius, first.endRadius);
    std::vector<Ring> rings{Ring{first.frame.position, heading(first.frame), first.frame.rotation * glm::vec3(1, 0, 0),
                                 first.startRadius, firstSlope, 0.0f}};
    for (size_t i = 0; i < segments.size(); ++i) {
        const Primitive& in = *segments[i];
        const glm::vec3 inHeading = heading(in.frame);
        const float inSlope = coneSlope(in.length, in.startRadius, in.endRadius);
        Ring ring{in.frame.position + in.length * inHeading,
                  inHeading,
                  rings.back().x,
                  in.endRadius,
                  inSlope,
                  rings.back().v + in.length};
        if (i + 1 < segments.size()) {
            const Primitive& out = *segments[i + 1];
            const glm::vec3 outHeading = heading(out.frame);
            ring.axis = unitOr(inHeading + outHeading, inHeading);
            ring.radius = 0.5f * (in.endRadius + out.startRadius);
            ring.slope = 0.5f * (inSlope + coneSlope(out.length, out.startRadius, out.endRadius));
            const glm::vec3 bend = outHeading - inHeading;
            if (glm::length(bend) > 1e-6f) {
                ring.bend = glm::normalize(bend);
                ring.stretch = 1.0f / std::max(glm::dot(ring.axis, inHeading), 0.5f);
            }
        }
        // Carry the previous ring's x into this plane: no twist along the tube.
        ring.x = unitOr(ring.x - ring.axis * glm::dot(ring.x, ring.axis), perpendicular(ring.axis));
        rings.push_back(ring);
    }
    return tubeMesh(rings, detail);
}

TriangleMesh bakedPrimitiveMesh(const PlantAsset& asset, const Primitive& primitive, const MeshDetail& detail) {
    TriangleMesh local;
    switch (primitive.kind) {
    case PrimitiveKind::Segment:
        local = segmentMesh(primitive.length, primitive.startRadius, primitive.endRadius, detail);
        break;
    case PrimitiveKind::Sphere: local = sphereMesh(primitive.startRadius, detail); break;
    case PrimitiveKind::Surface: local = surfaceMesh(asset.surfaces.at(primitive.shape)); break;
    case PrimitiveKind::Polygon: return polygonMesh(asset.polygons.at(primitive.shape).outline);
    }
    glm::mat4 transform = frameMatrix(primitive.frame);
    if (primitive.kind == PrimitiveKind::Surface) transform = glm::scale(transform, glm::vec3(primitive.length));
    TriangleMesh baked;
    baked.append(local, transform);
    return baked;
}

std::vector<TriangleMesh> meshesByMaterial(const PlantAsset& asset, SegmentGeometry segments,
                                           const MeshDetail& detail) {
    std::vector<TriangleMesh> meshes(asset.materials.size());
    const bool tubes = segments == SegmentGeometry::GeneralizedCylinders;
    for (const Primitive& primitive : asset.primitives) {
        if (!isDrawable(primitive) || (tubes && primitive.kind == PrimitiveKind::Segment)) continue;
        meshes.at(primitive.material).append(bakedPrimitiveMesh(asset, primitive, detail), glm::mat4(1.0f));
    }
    if (tubes) {
        const std::vector<TriangleMesh> chains = generalizedCylindersByMaterial(asset, detail);
        for (size_t m = 0; m < meshes.size(); ++m) meshes[m].append(chains[m], glm::mat4(1.0f));
    }
    return meshes;
}

std::vector<TriangleMesh> generalizedCylindersByMaterial(const PlantAsset& asset, const MeshDetail& detail) {
    std::vector<TriangleMesh> meshes(asset.materials.size());
    for (const SegmentChain& chain : segmentChains(asset)) {
        const uint32_t material = asset.primitives[chain.primitives.front()].material;
        meshes.at(material).append(generalizedCylinderMesh(asset, chain, detail), glm::mat4(1.0f));
    }
    return meshes;
}

uint64_t MeshSize::bytes() const {
    constexpr uint64_t kVertexBytes = 2 * sizeof(glm::vec3) + sizeof(glm::vec2);
    return bytesPlus(bytesTimes(vertices, kVertexBytes), bytesTimes(indices, sizeof(uint32_t)));
}

void MeshSize::add(const MeshSize& other) {
    vertices = bytesPlus(vertices, other.vertices);
    indices = bytesPlus(indices, other.indices);
}

MeshSize primitiveMeshSize(PrimitiveKind kind, const MeshSize& shape, const MeshDetail& detail) {
    switch (kind) {
    case PrimitiveKind::Segment: {
        const uint64_t sides = std::max(detail.segmentSides, 3u), ends = detail.segmentCaps ? 2 : 1;
        return {2 * ends * (sides + 1), 6 * ends * sides};
    }
    case PrimitiveKind::Sphere: {
        const uint64_t slices = std::max(detail.sphereSlices, 3u), stacks = std::max(detail.sphereStacks, 2u);
        return {(slices + 1) * (stacks + 1), 6 * slices * (stacks - 1)};
    }
    case PrimitiveKind::Surface: return shape;
    case PrimitiveKind::Polygon: return {shape.vertices, shape.vertices < 3 ? 0 : 3 * (shape.vertices - 2)};
    }
    return {};
}

MeshSize bakedMeshSize(const PlantAsset& asset, const MeshDetail& detail) {
    MeshSize total;
    for (const Primitive& primitive : asset.primitives) {
        if (!isDrawable(primitive)) continue;
        MeshSize shape;
        if (primitive.kind == PrimitiveKind::Surface && primitive.shape < asset.surfaces.size())
            shape = {asset.surfaces[primitive.shape].positions.size(), asset.surfaces[primitive.shape].indices.size()};
        if (primitive.kind == PrimitiveKind::Polygon && primitive.shape < asset.polygons.size())
            shape.vertices = asset.polygons[primitive.shape].outline.size();
        total.add(primitiveMeshSize(primitive.kind, shape, detail));
    }
    return total;
}

bool isDrawable(const Primitive& primitive) {
    switch (primitive.kind) {
    case PrimitiveKind::Segment:
        return primitive.length > 0.0f && std::max(primitive.startRadius, primitive.endRadius) > 0.0f;
    case PrimitiveKind::Sphere: return primitive.startRadius > 0.0f;
    case PrimitiveKind::Surface: return primitive.length > 0.0f;
    case PrimitiveKind::Polygon: return true;
    }
    return false;
}

glm::mat4 frameMatrix(const Frame& frame) {
    return glm::translate(glm::mat4(1.0f), frame.position) * glm::mat4_cast(frame.rotation);
}

} // namespace lsys
