// Shading shared by every pass: one sun, a sky dome, distance fog, tone map.
#include "shared/layouts.h"

#ifdef FIELD_FRAME
#include "shared/field_layouts.h"
#endif

layout(set = 0, binding = BINDING_FRAME_UNIFORMS, std140) uniform FrameBlock {
    FrameUniforms frame;
#ifdef FIELD_FRAME
    FieldFrame field; // shadow matrix, billboard axes, viewport, wind
#endif
};

// The powers are written as a square root and repeated squaring: a CPU
// rasteriser (lavapipe) evaluates pow as exp2(y·log2 x) with polynomials, and
// the sky is shaded at every pixel nothing covers.
vec3 skyRadiance(vec3 dir) {
    float up = clamp(dir.y, 0.0, 1.0);
    vec3 sky = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, sqrt(up));
    // Below the horizon the dome fades to a darker ground bounce.
    sky = dir.y < 0.0 ? mix(frame.skyHorizon.rgb, frame.groundAlbedo.rgb * 0.5, clamp(-dir.y * 4.0, 0.0, 1.0)) : sky;
    float sunDot = max(dot(dir, frame.sunDirection.xyz), 0.0);
    float sun2 = sunDot * sunDot, sun4 = sun2 * sun2, sun8 = sun4 * sun4;
    float sun16 = sun8 * sun8, sun32 = sun16 * sun16, sun64 = sun32 * sun32;
    sky += frame.sunRadiance.rgb * (0.02 * sun8 + 0.25 * sun64);
    sky += frame.sunRadiance.rgb * smoothstep(0.9995, 0.9998, sunDot) * 8.0;
    return sky;
}

// Fog per vertex (rgb: the sky seen along the view ray, a: amount): it
// changes slowly across a plant or a terrain cell, and the sky term is the
// most expensive part of shading a far, small plant (or a cloud's sphere).
vec4 vertexFog(vec3 worldPos) {
    vec3 toPoint = worldPos - frame.cameraPosition.xyz;
    float amount = 1.0 - exp(-length(toPoint) * frame.fog.x);
    return vec4(skyRadiance(normalize(vec3(toPoint.x, max(toPoint.y, 0.0), toPoint.z))), amount);
}

vec3 applyVertexFog(vec3 color, vec4 fog) {
    return mix(color, fog.rgb, fog.a);
}

// Lambert sun plus a hemispherical sky term that favours upward normals.
vec3 shadeDiffuse(vec3 albedo, vec3 normal, float occlusion) {
    float sun = max(dot(normal, frame.sunDirection.xyz), 0.0);
    float skyWeight = 0.5 + 0.5 * normal.y;
    vec3 ambient = mix(frame.groundAlbedo.rgb * frame.skyHorizon.rgb, frame.skyZenith.rgb, skyWeight);
    return albedo * (frame.sunRadiance.rgb * sun + ambient * occlusion);
}

// Narkowicz's fit of the ACES filmic curve; the sRGB attachment encodes gamma.
vec3 toneMap(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Deterministic value noise for surface variation (no textures yet).
float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

float valueNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash12(i), hash12(i + vec2(1, 0)), u.x),
               mix(hash12(i + vec2(0, 1)), hash12(i + vec2(1, 1)), u.x), u.y);
}
