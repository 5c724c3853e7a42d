#version 460
// Traces a buffer of rays through a packed InstanceGraph, one invocation a
// ray, and writes each one's hit (engine/raytrace/raytrace_pass.h).
#extension GL_GOOGLE_include_directive : require

#include "raytrace_traverse.glsl"

layout(local_size_x = RAYTRACE_GROUP_SIZE) in;

layout(push_constant) uniform Push {
    RtTracePush push;
};
layout(std430, set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_RAYS) readonly buffer Rays {
    RtRay rays[];
};
layout(std430, set = RAYTRACE_GRAPH_SET, binding = RAYTRACE_BINDING_HITS) writeonly buffer Hits {
    RtHit hits[];
};

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= push.rayCount) return;
    RtRay ray = rays[index];
    RtTraceHit traced =
        rtTrace(ray.origin, ray.direction, ray.tMin, ray.tMax, push.rootNode, push.query == RAYTRACE_QUERY_ANY);
    RtHit hit = RtHit(vec3(0.0), 0.0, RAYTRACE_NO_HIT, 0, 0, traced.stackUsed);
    if (traced.primitive != RAYTRACE_NO_HIT) {
        RtPrimitive primitive = rtPrimitiveAt(traced.primitive);
        hit = RtHit(traced.normal, traced.t, traced.primitive, primitive.kind, primitive.material, traced.stackUsed);
    }
    hits[index] = hit;
}
