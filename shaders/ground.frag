#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 0) out vec4 outColor;

void main() {
    vec2 p = inWorldPos.xz;
    // Two octaves of noise give patches of lighter and darker grass.
    float n = 0.65 * valueNoise(p * 0.35) + 0.35 * valueNoise(p * 2.1);
    vec3 albedo = frame.groundAlbedo.rgb * mix(0.7, 1.25, n);
    // Darken around the origin where the plant stands: cheap contact occlusion.
    float contact = mix(0.55, 1.0, smoothstep(0.0, 1.6, length(p)));
    vec3 color = shadeDiffuse(albedo, vec3(0.0, 1.0, 0.0), 1.0) * contact;
    outColor = vec4(toneMap(applyFog(color, inWorldPos)), 1.0);
}
