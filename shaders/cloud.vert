#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
#include "shared/cloud_layouts.h"

// One camera-facing quad per sphere of a cloud (instance i: the i-th
// billboard, farthest first), at the sphere's centre.
layout(set = 0, binding = CLOUD_BINDING_SPHERES) uniform usamplerBuffer billboardTexels; // CloudBillboard[]

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) flat out vec4 outSphere; // xyz centre, w radius
layout(location = 2) flat out vec4 outFog;    // vertexFog at the centre: a sphere is small against its distance
layout(location = 3) flat out vec4 outShade; // CloudBillboard::shade

const vec2 kCorners[CLOUD_BILLBOARD_VERTICES] =
    vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    int t = gl_InstanceIndex * CLOUD_BILLBOARD_TEXELS;
    vec4 sphere = uintBitsToFloat(texelFetch(billboardTexels, t));
    vec4 shade = uintBitsToFloat(texelFetch(billboardTexels, t + 1));
    vec3 toCamera = frame.cameraPosition.xyz - sphere.xyz;
    float distance = length(toCamera);
    vec3 facing = toCamera / max(distance, 1e-6);
    vec3 side = abs(facing.y) > 0.999 ? vec3(1.0, 0.0, 0.0) : normalize(cross(vec3(0.0, 1.0, 0.0), facing));
    vec3 up = cross(facing, side);
    // The cone of rays touching the sphere meets the quad's plane (through
    // the centre) in a circle of radius r·D/√(D²−r²). A camera inside the
    // sphere sees no quad: the sphere collapses to a point.
    float r = sphere.w;
    float reach = distance > 1.01 * r ? r * distance / sqrt(distance * distance - r * r) : 0.0;
    vec2 corner = kCorners[gl_VertexIndex];
    outWorldPos = sphere.xyz + (side * corner.x + up * corner.y) * reach;
    outSphere = sphere;
    outFog = vertexFog(sphere.xyz);
    outShade = shade;
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
}
