#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

// A semi-transparent sphere of a cloud (the clouds-and-mountains chapter, §23–24), premultiplied:
// its opacity is the light the sphere's thickness along the pixel's ray
// absorbs, so the rim, where the ray only grazes it, fades out smoothly.
// Lit by the sun with a wrapped term (light scattered through the cloud
// reaches the side away from the sun, dimmed) on a normal that leans to the
// side of the whole cloud the sphere is on, so the cloud is lit as one body
// rather than as a heap of balls; darker towards the cloud's bottom, where
// less light gets through the cloud above; the cloud's outline seen against
// the sun glows (forward scattering, the silver lining); fogged as every other pass
// is (vertexFog).
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) flat in vec4 inSphere;
layout(location = 2) flat in vec4 inFog;
layout(location = 3) flat in vec4 inShade; // x height in the cloud, yzw the cloud's outward normal
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

    vec3 surface = offset / r - ray * halfChord; // the sphere's normal where the ray enters it
    vec3 normal = normalize(mix(surface, inShade.yzw, 0.6));
    vec3 sun = frame.sunDirection.xyz;
    float sunward = 0.5 + 0.5 * dot(normal, sun);
    float lift = clamp(0.6 * inShade.x + 0.4 * (0.5 + 0.5 * normal.y), 0.0, 1.0);
    vec3 ambient = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5 + 0.5 * normal.y);
    float towardSun = max(dot(ray, sun), 0.0);
    float t2 = towardSun * towardSun, t4 = t2 * t2, t8 = t4 * t4; // as skyRadiance: no pow on lavapipe
    float silver = t8 * (1.0 - abs(dot(inShade.yzw, ray))); // at the cloud's outline, not each sphere's
    vec3 radiance = kAlbedo * (frame.sunRadiance.rgb * (sunward * mix(0.2, 1.0, lift) + silver) +
                               ambient * mix(0.45, 1.0, lift));
    outColor = vec4(toneMap(applyVertexFog(radiance, inFog)) * alpha, alpha);
}
