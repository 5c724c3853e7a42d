// The ground's colour (terrain.frag, terrain_sunlit.frag): grass-covered
// ground, patches of lighter and darker grass, bare earth on steep slopes,
// lit by the sun and the sky.
#include "field_common.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inFog;
layout(location = 3) in float inBroadPatches; // terrain.vert: terrainBroadPatches
layout(location = 4) in vec3 inSunMap;        // terrain.vert: sunMapPosition, from the vertex normal
layout(location = 0) out vec4 outColor;

// `shadowed`: a constant of each shader, false for chunks the sun's map does
// not reach (terrain_chunks.h), whose shader then has no shadow lookup at all
// (on lavapipe a branch would not skip it).
vec4 groundColor(const bool shadowed) {
    vec3 n = normalize(inNormal);
    vec2 p = inWorldPos.xz;
    float patches = inBroadPatches + 0.3 * valueNoise(p * 0.6) + 0.15 * valueNoise(p * 4.0);
    vec3 grass = frame.groundAlbedo.rgb * mix(0.65, 1.3, patches);
    vec3 earth = vec3(0.16, 0.12, 0.08) * mix(0.8, 1.1, valueNoise(p * 1.7));
    float slope = 1.0 - n.y;
    vec3 albedo = mix(grass, earth, smoothstep(0.18, 0.35, slope + 0.1 * (patches - 0.5)));
    vec3 color = shadeFieldSeen(albedo, n, shadowed ? sunVisibilityOf(gl_FragCoord.xy, inSunMap) : 1.0, 1.0, 0.0);
    return vec4(toneMap(applyVertexFog(color, inFog)), 1.0);
}
