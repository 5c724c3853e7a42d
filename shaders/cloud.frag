#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

// A semi-transparent sphere of a cloud (seed 002, ch. 24), premultiplied:
// its opacity is the light the sphere's thickness along the pixel's ray
// absorbs, so the rim, where the ray only grazes it, fades out smoothly.
// Lit by the sun with a wrapped term (light scattered through the cloud
// reaches the side away from the sun, dimmed) and darker towards the
// cloud's bottom, where less light gets through the cloud above; fogged as
// every other pass is (vertexFog).
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) flat in vec4 inSphere;
layout(location = 2) flat in vec4 inFog;
layout(location = 3) flat in float inHeight;
layout(location = 0) out vec4 outColor;

// Extinction per radius of path: the ray through the centre (two radii) is
// 1 − e^(−2.4) ≈ 91 % opaque.
const float kExtinction = 1.2;
const vec3 kAlbedo = vec3(0.92);

void main() {
    vec3 eye = frame.cameraPosition.xyz;
    vec3 ray = normalize(inWorldPos - eye);
    vec3 toCentre = inSphere.xyz - eye;
    vec3 offset = ray * dot(toCentre, ray) - toCentre; // from the centre to the ray's closest point
    float r = inSphere.w;
    float miss = dot(offset, offset) / (r * r); // (closest distance / r)²
    if (miss >= 1.0) discard;
    float halfChord = sqrt(1.0 - miss); // in radii
    float alpha = (1.0 - exp(-kExtinction * 2.0 * halfChord)) * smoothstep(0.0, 0.5, halfChord);

    vec3 normal = offset / r - ray * halfChord; // where the ray enters the sphere
    float sunward = 0.5 + 0.5 * dot(normal, frame.sunDirection.xyz);
    float lift = clamp(0.6 * inHeight + 0.4 * (0.5 + 0.5 * normal.y), 0.0, 1.0);
    vec3 ambient = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5 + 0.5 * normal.y);
    vec3 radiance = kAlbedo * (frame.sunRadiance.rgb * sunward * mix(0.2, 1.0, lift) + ambient * mix(0.45, 1.0, lift));
    outColor = vec4(toneMap(applyVertexFog(radiance, inFog)) * alpha, alpha);
}
