#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

// Instanced cone frustums: the unit cylinder mesh is pulled from a storage
// buffer and stretched from each instance's start to its end point.
layout(set = 0, binding = BINDING_SEGMENT_INSTANCES, std430) readonly buffer Segments {
    SegmentInstance segments[];
};
layout(set = 0, binding = BINDING_MESH_VERTICES, std430) readonly buffer Vertices {
    MeshVertex vertices[];
};

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outAlbedo;
layout(location = 3) out float outAlong;

void main() {
    SegmentInstance s = segments[gl_InstanceIndex];
    MeshVertex v = vertices[gl_VertexIndex];

    vec3 axis = s.endRadius.xyz - s.startRadius.xyz;
    float len = max(length(axis), 1e-6);
    vec3 dir = axis / len;
    // Any unit vector not parallel to dir gives a frame around the axis.
    vec3 helper = abs(dir.y) < 0.99 ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 bx = normalize(cross(helper, dir));
    vec3 bz = cross(dir, bx);

    float radius = mix(s.startRadius.w, s.endRadius.w, v.position.y);
    vec3 radial = bx * v.position.x + bz * v.position.z;
    outWorldPos = s.startRadius.xyz + axis * v.position.y + radial * radius;

    // Side normals tilt toward the narrow end by the taper slope.
    vec3 sideNormal = normalize(radial * len + dir * (s.startRadius.w - s.endRadius.w));
    outNormal = v.normal.w > 0.5 ? sideNormal : dir * v.normal.y;
    outAlbedo = s.albedo.rgb;
    outAlong = v.position.y;
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
}
