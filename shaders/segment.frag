#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inAlbedo;
layout(location = 3) in float inAlong;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 n = normalize(inNormal);
    // Bark streaks along the segment and a little occlusion near the ground.
    float streak = valueNoise(vec2(atan(n.z, n.x) * 6.0, inAlong * 3.0));
    vec3 albedo = inAlbedo * mix(0.8, 1.1, streak);
    float occlusion = mix(0.45, 1.0, clamp(inWorldPos.y * 0.8, 0.0, 1.0));
    vec3 color = shadeDiffuse(albedo, n, occlusion);
    outColor = vec4(toneMap(applyFog(color, inWorldPos)), 1.0);
}
