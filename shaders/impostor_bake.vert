#version 460
#extension GL_GOOGLE_include_directive : require
#include "plant_surface.glsl"

// One frame of the impostor bake (engine/field/impostor_atlas.h): a model's LOD0
// mesh seen orthographically along the push constants' axes, fitted to the
// model's box (a colour frame from the side, a shadow frame from the sun).
layout(set = 0, binding = IMPOSTOR_BAKE_BINDING_VERTICES, std430) readonly buffer Vertices {
    FieldVertex vertices[];
};

layout(push_constant) uniform BakeBlock {
    ImpostorBakePush bake;
};

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outAlbedo;
layout(location = 2) out vec2 outUv;
layout(location = 3) flat out float outKind;

void main() {
    FieldVertex v = vertices[gl_VertexIndex];
    vec3 p = v.position.xyz;
    // Row 0 of the frame is the top of the view; depth 0 its front, 1 its back.
    float x = dot(p, bake.right.xyz) + bake.right.w;
    float y = -(dot(p, bake.up.xyz) + bake.up.w);
    float depth = 0.5 - 0.5 * (dot(p, bake.toView.xyz) + bake.toView.w);
    gl_Position = vec4(x, y, depth, 1.0);
    outNormal = v.normal.xyz;
    outAlbedo = v.albedo.rgb;
    outUv = vec2(v.position.w, v.normal.w);
    outKind = v.albedo.a;
}
