#version 460
// The traced-sun pass's rays (engine/field/raytraced_sun_pass.h): from each
// pixel's origin towards the sun through the field's graph, the first hit
// ending it (Robbins 1998, "Branching Shadows", ends shadow rays so).
#extension GL_GOOGLE_include_directive : require

#define RAYTRACE_CUT_OUT
#include "raytrace_traverse.glsl"
#include "plant_surface.glsl"
#include "shared/raytraced_sun_layouts.h"

layout(local_size_x = RAYTRACED_SUN_GROUP_SIZE, local_size_y = RAYTRACED_SUN_GROUP_SIZE) in;

layout(push_constant) uniform Push {
    RaytracedSunPush push;
};
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACED_SUN_BINDING_ORIGINS, rgba32f) uniform readonly image2D origins;
layout(set = RAYTRACE_GRAPH_SET, binding = RAYTRACED_SUN_BINDING_VISIBILITY, r32f) uniform writeonly image2D visibility;

// A leaf card's hit outside the leaf's outline is no hit: the card's corners
// keep their texture coordinates in w (engine/raytrace/field_graph.h).
bool rtCutOut(uint material, uint triangle, vec2 barycentric) {
    if (material != RAYTRACED_SUN_LEAF_CARD_MATERIAL) return false;
    int t = int(triangle) * RAYTRACE_TRIANGLE_TEXELS;
    vec2 a = unpackHalf2x16(texelFetch(rtTriangleTexels, t).w);
    vec2 b = unpackHalf2x16(texelFetch(rtTriangleTexels, t + 1).w);
    vec2 c = unpackHalf2x16(texelFetch(rtTriangleTexels, t + 2).w);
    return leafCutOut(a * (1.0 - barycentric.x - barycentric.y) + b * barycentric.x + c * barycentric.y);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), push.frame.xy))) return;
    vec4 origin = imageLoad(origins, pixel);
    float lit = 1.0;
    if (origin.w > 0.5) {
        RtTraceHit hit = rtTrace(origin.xyz, push.sun.xyz, 0.0, push.sun.w, push.frame.z, true);
        lit = hit.primitive == RAYTRACE_NO_HIT ? 1.0 : 0.0;
    }
    imageStore(visibility, pixel, vec4(lit));
}
