// The hierarchical traversal of lsys::trace(GraphTracer) on the GPU
// (docs/RAYTRACING.md, "The GPU traversal"), over the graph packed by
// engine/raytrace/gpu_graph.h. The includer defines RAYTRACE_GRAPH_SET, the
// set holding the graph's buffers (0 when it does not), and may define
// RAYTRACE_CUT_OUT and then, after the include, the function
// `bool rtCutOut(uint material, uint triangle, vec2 barycentric)`: true
// where a hit on a polygon's triangle is to be ignored (the transparent
// part of an alpha-tested leaf card, so its shadow has the leaf's outline).
//
// GLSL has no recursion: one stack holds the nodes still to visit of every
// object on the way down, each entry with its instance level, and the ray in
// each level's space is kept per level. A leaf whose instance is entered
// leaves the rest of its items on the stack, so the child is walked whole
// before them, in the CPU's order. The shape tests run in single precision,
// made stable where the CPU's double precision hides it: the quadratics are
// solved from the point of the ray nearest the shape (Haines et al.,
// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems,
// 2019, ch. 7), in the form that does not cancel (Press et al.,
// Numerical Recipes §5.6).
#ifndef PLANTFIELD_SHADERS_RAYTRACE_TRAVERSE_GLSL
#define PLANTFIELD_SHADERS_RAYTRACE_TRAVERSE_GLSL

#include "shared/raytrace_layouts.h"

#ifndef RAYTRACE_GRAPH_SET
#define RAYTRACE_GRAPH_SET 0
#endif

// The graph is read through uniform texel buffers (uint views, 16-byte
// texels, a record's stride in RAYTRACE_*_TEXELS; items and object roots
// 4-byte texels): lavapipe gathers a texel for all SIMD lanes at once, where
// it reads a storage buffer at a per-invocation index one lane at a time.
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_NODES) uniform usamplerBuffer rtNodeTexels;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_ITEMS) uniform usamplerBuffer rtItemTexels;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_OBJECT_ROOTS) uniform usamplerBuffer rtObjectRootTexels;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_INSTANCES) uniform usamplerBuffer rtInstanceTexels;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_PRIMITIVES) uniform usamplerBuffer rtPrimitiveTexels;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_TRIANGLES) uniform usamplerBuffer rtTriangleTexels;

#ifdef RAYTRACE_CUT_OUT
bool rtCutOut(uint material, uint triangle, vec2 barycentric);
#endif

RtNode rtNodeAt(uint i) {
    int t = int(i) * RAYTRACE_NODE_TEXELS;
    uvec4 low = texelFetch(rtNodeTexels, t), high = texelFetch(rtNodeTexels, t + 1);
    return RtNode(uintBitsToFloat(low.xyz), low.w, uintBitsToFloat(high.xyz), high.w);
}

uint rtItemAt(uint i) { return texelFetch(rtItemTexels, int(i)).x; }
uint rtObjectRootAt(uint i) { return texelFetch(rtObjectRootTexels, int(i)).x; }

RtInstance rtInstanceAt(uint i) {
    int t = int(i) * RAYTRACE_INSTANCE_TEXELS;
    uvec4 placed = texelFetch(rtInstanceTexels, t + 1);
    return RtInstance(uintBitsToFloat(texelFetch(rtInstanceTexels, t)), uintBitsToFloat(placed.xyz), placed.w,
                      uintBitsToFloat(texelFetch(rtInstanceTexels, t + 2).x), 0, 0, 0);
}

RtPrimitive rtPrimitiveAt(uint i) {
    int t = int(i) * RAYTRACE_PRIMITIVE_TEXELS;
    uvec4 placed = texelFetch(rtPrimitiveTexels, t + 1), size = texelFetch(rtPrimitiveTexels, t + 2);
    uvec4 triangles = texelFetch(rtPrimitiveTexels, t + 3);
    return RtPrimitive(uintBitsToFloat(texelFetch(rtPrimitiveTexels, t)), uintBitsToFloat(placed.xyz), placed.w,
                       uintBitsToFloat(size.x), uintBitsToFloat(size.y), uintBitsToFloat(size.z), size.w, triangles.x,
                       triangles.y, 0, 0);
}

RtTriangle rtTriangleAt(uint i) {
    int t = int(i) * RAYTRACE_TRIANGLE_TEXELS;
    return RtTriangle(uintBitsToFloat(texelFetch(rtTriangleTexels, t)),
                      uintBitsToFloat(texelFetch(rtTriangleTexels, t + 1)),
                      uintBitsToFloat(texelFetch(rtTriangleTexels, t + 2)));
}

// q·v·q* as glm computes it (a unit quaternion, xyz w).
vec3 rtRotate(vec4 q, vec3 v) {
    vec3 uv = cross(q.xyz, v);
    return v + 2.0 * (uv * q.w + cross(q.xyz, uv));
}
vec3 rtRotateBack(vec4 q, vec3 v) { return rtRotate(vec4(-q.xyz, q.w), v); }

// As lsys::boxEntry: where the ray enters the box, clamped to tMin.
bool rtBoxEntry(vec3 o, vec3 d, float tMin, float tMax, vec3 boxMin, vec3 boxMax, out float entry) {
    float enter = tMin, leave = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < boxMin[axis] || o[axis] > boxMax[axis]) return false;
            continue;
        }
        float near = (boxMin[axis] - o[axis]) / d[axis], far = (boxMax[axis] - o[axis]) / d[axis];
        enter = max(enter, min(near, far));
        leave = min(leave, max(near, far));
        if (enter > leave) return false;
    }
    entry = enter;
    return true;
}

// The nearest hit of one shape in [tMin, tMax] (lsys's Nearest).
struct RtNearest {
    float tMin;
    float tMax;
    float t;
    vec3 normal;
    bool found;
};

void rtOffer(inout RtNearest n, float t, vec3 normal) {
    if (!(t >= n.tMin && t <= n.tMax) || (n.found && t >= n.t)) return;
    n.t = t;
    n.normal = normal;
    n.found = true;
}

// The parameter of the point of the ray nearest `centre`: the shape tests
// solve from there, where the ray's coordinates are as small as the shape.
float rtNearestTo(vec3 o, vec3 d, vec3 centre) { return dot(centre - o, d) / dot(d, d); }

// A root s of the frustum's side, on the ray from p0 (t = shift + s).
void rtOfferFrustumSide(inout RtNearest n, vec3 p0, vec3 d, float shift, float s, float l, float r0, float slope) {
    vec3 p = p0 + s * d;
    float radius = r0 + slope * p.y;
    if (p.y < 0.0 || p.y > l || radius < 0.0) return;
    rtOffer(n, shift + s, vec3(p.x, -slope * radius, p.z)); // the gradient of x² + z² − r(y)²
}

// As lsys::intersectFrustum: the closed cone frustum along +Y.
void rtFrustum(inout RtNearest n, vec3 o, vec3 d, float l, float r0, float r1) {
    if (!(l > 0.0)) return;
    float shift = rtNearestTo(o, d, vec3(0.0, 0.5 * l, 0.0));
    vec3 p0 = o + shift * d;
    float slope = (r1 - r0) / l;
    float radiusAtP0 = r0 + slope * p0.y;
    float a = d.x * d.x + d.z * d.z - slope * slope * d.y * d.y;
    float b = 2.0 * (p0.x * d.x + p0.z * d.z - slope * d.y * radiusAtP0);
    float c = p0.x * p0.x + p0.z * p0.z - radiusAtP0 * radiusAtP0;
    if (a == 0.0) {
        if (b != 0.0) rtOfferFrustumSide(n, p0, d, shift, -c / b, l, r0, slope);
    } else {
        float discriminant = b * b - 4.0 * a * c;
        if (discriminant >= 0.0) {
            float root = sqrt(discriminant);
            float q = -0.5 * (b + (b < 0.0 ? -root : root));
            rtOfferFrustumSide(n, p0, d, shift, q / a, l, r0, slope);
            if (q != 0.0) rtOfferFrustumSide(n, p0, d, shift, c / q, l, r0, slope);
        }
    }
    if (d.y != 0.0) {
        for (int cap = 0; cap < 2; ++cap) {
            float height = cap == 0 ? 0.0 : l, radius = cap == 0 ? r0 : r1;
            float s = (height - p0.y) / d.y;
            vec3 p = p0 + s * d;
            if (radius > 0.0 && p.x * p.x + p.z * p.z <= radius * radius)
                rtOffer(n, shift + s, vec3(0.0, cap == 0 ? -1.0 : 1.0, 0.0));
        }
    }
}

// As lsys::intersectSphere, from the point of the ray nearest the centre:
// its distance² to the centre gives the half chord without cancellation.
void rtSphere(inout RtNearest n, vec3 o, vec3 d, float radius) {
    float shift = rtNearestTo(o, d, vec3(0.0));
    vec3 p0 = o + shift * d;
    float halfChord2 = radius * radius - dot(p0, p0);
    if (halfChord2 < 0.0) return;
    float s = sqrt(halfChord2 / dot(d, d));
    rtOffer(n, shift - s, p0 - s * d);
    rtOffer(n, shift + s, p0 + s * d);
}

// As lsys::intersectTriangle (Möller and Trumbore 1997), from either side;
// true with t, the unnormalised normal (b − a) × (c − a) and the hit's
// barycentric coordinates of b and c on a hit in [tMin, tMax].
bool rtTriangle(vec3 o, vec3 d, float tMin, float tMax, RtTriangle tri, out float t, out vec3 normal,
                out vec2 barycentric) {
    vec3 edge1 = tri.b.xyz - tri.a.xyz, edge2 = tri.c.xyz - tri.a.xyz;
    vec3 p = cross(d, edge2);
    float determinant = dot(edge1, p);
    if (determinant == 0.0) return false;
    float inverse = 1.0 / determinant;
    vec3 s = o - tri.a.xyz;
    float u = dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, edge1);
    float v = dot(d, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return false;
    t = dot(edge2, q) * inverse;
    normal = cross(edge1, edge2);
    barycentric = vec2(u, v);
    return t >= tMin && t <= tMax;
}

// The nearest of a primitive's triangles, each tested up to the nearest so
// far (as lsys's nearestTriangle); a polygon's hits the includer cuts out
// are not hits.
void rtNearestTriangle(inout RtNearest n, vec3 o, vec3 d, uint first, uint count, uint material, bool polygon) {
    for (uint i = first; i < first + count; ++i) {
        float t;
        vec3 normal;
        vec2 barycentric;
        if (rtTriangle(o, d, n.tMin, n.tMax, rtTriangleAt(i), t, normal, barycentric)) {
#ifdef RAYTRACE_CUT_OUT
            if (polygon && rtCutOut(material, i, barycentric)) continue;
#endif
            n.t = n.tMax = t;
            n.normal = normal;
            n.found = true;
        }
    }
}

// As lsys::tracePrimitive, the ray in the space of the primitive's frame's
// parent: true on a hit nearer than tMax, which is lowered to it; the
// normal (unit) in the ray's space.
bool rtTracePrimitive(RtPrimitive primitive, vec3 o, vec3 d, float tMin, inout float tMax, out vec3 normal) {
    RtNearest n = RtNearest(tMin, tMax, 0.0, vec3(0.0), false);
    if (primitive.kind == RAYTRACE_KIND_POLYGON) {
        rtNearestTriangle(n, o, d, primitive.firstTriangle, primitive.triangleCount, primitive.material, true);
    } else {
        vec3 localO = rtRotateBack(primitive.rotation, o - primitive.position);
        vec3 localD = rtRotateBack(primitive.rotation, d);
        if (primitive.kind == RAYTRACE_KIND_SEGMENT)
            rtFrustum(n, localO, localD, primitive.extent, primitive.startRadius, primitive.endRadius);
        else if (primitive.kind == RAYTRACE_KIND_SPHERE)
            rtSphere(n, localO, localD, primitive.startRadius);
        else // a surface's unit mesh, scaled by its length (t is unchanged)
            rtNearestTriangle(n, localO / primitive.extent, localD / primitive.extent, primitive.firstTriangle,
                              primitive.triangleCount, primitive.material, false);
        n.normal = rtRotate(primitive.rotation, n.normal);
    }
    if (!n.found) return false;
    float norm = length(n.normal);
    normal = norm > 0.0 ? n.normal / norm : vec3(0.0, 1.0, 0.0);
    tMax = n.t;
    return true;
}

struct RtStackEntry {
    uint node;
    uint level;
    uint item; // the first item of a leaf still to visit (0 for a node not yet entered)
    float entry;
};

struct RtTraceHit {
    float t;
    uint primitive;
    vec3 normal;
    uint stackUsed; // the most entries the stack held
};

// As lsys::trace(GraphTracer): the nearest hit in [tMin, tMax] (anyHit
// false) or the first found, from the root object's root node; primitive
// is RAYTRACE_NO_HIT when nothing was hit.
RtTraceHit rtTrace(vec3 origin, vec3 direction, float tMin, float tMax, uint rootNode, bool anyHit) {
    RtTraceHit hit = RtTraceHit(tMax, RAYTRACE_NO_HIT, vec3(0.0), 0);
    // The ray in each level's space, and the rotation of the instance that
    // placed the level in the one above (which turns a normal back).
    vec3 levelOrigin[RAYTRACE_MAX_LEVELS], levelDirection[RAYTRACE_MAX_LEVELS];
    vec4 levelRotation[RAYTRACE_MAX_LEVELS];
    levelOrigin[0] = origin;
    levelDirection[0] = direction;
    RtStackEntry stack[RAYTRACE_STACK_SIZE];
    uint size = 0;
    float entry;
    if (rootNode != RAYTRACE_NO_NODE &&
        rtBoxEntry(origin, direction, tMin, tMax, rtNodeAt(rootNode).boundsMin, rtNodeAt(rootNode).boundsMax, entry))
        stack[size++] = RtStackEntry(rootNode, 0, 0, entry);
    while (size > 0) {
        hit.stackUsed = max(hit.stackUsed, size);
        RtStackEntry top = stack[--size];
        if (top.entry > tMax) continue; // a nearer hit was found since it was pushed
        vec3 o = levelOrigin[top.level], d = levelDirection[top.level];
        RtNode node = rtNodeAt(top.node);
        if (node.count == 0) {
            uint a = node.first, b = node.first + 1;
            float entryA, entryB;
            bool hitA = rtBoxEntry(o, d, tMin, tMax, rtNodeAt(a).boundsMin, rtNodeAt(a).boundsMax, entryA);
            bool hitB = rtBoxEntry(o, d, tMin, tMax, rtNodeAt(b).boundsMin, rtNodeAt(b).boundsMax, entryB);
            // The nearer is pushed last, so it is visited first (the first on a tie, as lsys::traverseBvh).
            if (hitB && (!hitA || entryB < entryA)) {
                if (hitA) stack[size++] = RtStackEntry(a, top.level, 0, entryA);
                stack[size++] = RtStackEntry(b, top.level, 0, entryB);
            } else if (hitA) {
                if (hitB) stack[size++] = RtStackEntry(b, top.level, 0, entryB);
                stack[size++] = RtStackEntry(a, top.level, 0, entryA);
            }
            continue;
        }
        for (uint i = top.item; i < node.count; ++i) {
            uint item = rtItemAt(node.first + i);
            if ((item & RAYTRACE_ITEM_INSTANCE) == 0) {
                vec3 normal;
                if (rtTracePrimitive(rtPrimitiveAt(item), o, d, tMin, tMax, normal)) {
                    // Back to the traced ray's space, level by level as the CPU's recursion returns.
                    for (uint level = top.level; level > 0; --level)
                        normal = normalize(rtRotate(levelRotation[level], normal));
                    hit.t = tMax;
                    hit.primitive = item;
                    hit.normal = normal;
                    if (anyHit) return hit;
                }
                continue;
            }
            RtInstance instance = rtInstanceAt(item & ~RAYTRACE_ITEM_INSTANCE);
            uint childRoot = rtObjectRootAt(instance.object);
            uint child = top.level + 1;
            // Scaled with the child, the direction keeps t the same parameter in both spaces.
            levelOrigin[child] = rtRotateBack(instance.rotation, o - instance.position) / instance.scale;
            levelDirection[child] = rtRotateBack(instance.rotation, d) / instance.scale;
            levelRotation[child] = instance.rotation;
            if (childRoot == RAYTRACE_NO_NODE ||
                !rtBoxEntry(levelOrigin[child], levelDirection[child], tMin, tMax, rtNodeAt(childRoot).boundsMin,
                            rtNodeAt(childRoot).boundsMax, entry))
                continue;
            // The child is walked whole before the rest of this leaf.
            if (i + 1 < node.count) stack[size++] = RtStackEntry(top.node, top.level, i + 1, top.entry);
            stack[size++] = RtStackEntry(childRoot, child, 0, entry);
            break;
        }
    }
    return hit;
}

#endif
