#version 460
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
#include "shared/cloud_layouts.h"

// The shade a cloud's shadow gives the ground: the sunlight the clouds let
// through where the sun's ray from this point meets the plane y = 0
// (cloudShadowPlanePoint), the map moved with the clouds' drift, read
// bilinearly; the sun's share of the ground's light is scaled by it, and
// the fog in front of the ground (vertexFog's amount) is left as it is.
layout(set = 0, binding = CLOUD_SHADOW_BINDING_MAP) uniform usamplerBuffer mapTexels; // float per texel
layout(push_constant) uniform CloudShadowBlock {
    CloudShadowPush shadow;
};

layout(location = 0) in vec3 inWorldPos;
layout(location = 0) out vec4 outShade;

// Clamped to the map, whose border texels are 1 (bakeCloudShadows): no
// branch on the drift, which lavapipe would otherwise compile a shader
// variant for every frame (docs/ARCHITECTURE.md, "What a shader may branch on").
float transmittanceAt(ivec2 texel) {
    ivec2 size = ivec2(shadow.grid.w, shadow.drift.w);
    ivec2 inside = clamp(texel, ivec2(0), size - 1);
    return uintBitsToFloat(texelFetch(mapTexels, inside.y * size.x + inside.x).x);
}

void main() {
    vec3 sun = frame.sunDirection.xyz;
    vec2 plane = inWorldPos.xz - sun.xz * (inWorldPos.y / sun.y) - shadow.drift.xz;
    vec2 at = (plane - shadow.grid.xy) * shadow.grid.z;
    ivec2 texel = ivec2(floor(at));
    vec2 f = at - vec2(texel);
    float light = mix(mix(transmittanceAt(texel), transmittanceAt(texel + ivec2(1, 0)), f.x),
                      mix(transmittanceAt(texel + ivec2(0, 1)), transmittanceAt(texel + ivec2(1, 1)), f.x), f.y);
    float fog = 1.0 - exp(-length(inWorldPos - frame.cameraPosition.xyz) * frame.fog.x);
    float shade = 1.0 - CLOUD_SHADOW_SUN_SHARE * (1.0 - light) * (1.0 - fog);
    outShade = vec4(shade, shade, shade, 1.0);
}
