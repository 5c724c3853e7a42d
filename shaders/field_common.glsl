// Bindings and helpers of the field's draw passes (plants, impostors,
// terrain, shadows): one descriptor set, layouts from field_layouts.h.
#ifndef FIELD_COMMON_GLSL
#define FIELD_COMMON_GLSL
#define FIELD_FRAME
#include "common.glsl"
#include "plant_surface.glsl"
#include "shared/joint_physics.h"
#include "texels.glsl"

// Everything the draw shaders read per vertex or per plant is a uniform
// texel buffer (uint views, 16-byte texels unless said, a struct's stride in
// texels named in field_layouts.h; texels.glsl says why).
layout(set = 0, binding = FIELD_BINDING_INSTANCES) uniform usamplerBuffer instanceTexels; // FieldInstance[]
layout(set = 0, binding = FIELD_BINDING_VISIBLE) uniform usamplerBuffer visibleTexels;   // uint (4-byte texels)
layout(set = 0, binding = FIELD_BINDING_VERTICES) uniform usamplerBuffer vertexTexels;   // FieldVertex[]
layout(set = 0, binding = FIELD_BINDING_MODELS) uniform usamplerBuffer modelTexels;      // PlantModel[]
layout(set = 0, binding = FIELD_BINDING_ATLAS_COLOR) uniform sampler2DArray atlasColor;
layout(set = 0, binding = FIELD_BINDING_ATLAS_NORMAL) uniform sampler2DArray atlasNormal;
layout(set = 0, binding = FIELD_BINDING_IMPOSTOR_SHADOW) uniform sampler2DArray impostorShadow;
layout(set = 0, binding = FIELD_BINDING_SHADOW) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = FIELD_BINDING_TERRAIN) uniform usamplerBuffer terrainTexels;   // TerrainVertex[]
layout(set = 0, binding = FIELD_BINDING_SKELETONS) uniform usamplerBuffer skeletonTexels; // Skeleton[]
layout(set = 0, binding = FIELD_BINDING_POSES) uniform usamplerBuffer poseTexels;        // JointPose[]
layout(set = 0, binding = FIELD_BINDING_INSTANCE_SKELETON) uniform usamplerBuffer instanceSkeletonTexels; // uint
layout(set = 0, binding = FIELD_BINDING_IMPOSTOR_OUTLINES) uniform usamplerBuffer outlineTexels; // per atlas layer
layout(set = 0, binding = FIELD_BINDING_RAYTRACED_SUN) uniform sampler2D raytracedSun; // per pixel (r)

FieldInstance fieldInstanceAt(uint i) {
    int t = int(i) * FIELD_INSTANCE_TEXELS;
    return FieldInstance(floatTexel(instanceTexels, t), floatTexel(instanceTexels, t + 1),
                         texelFetch(instanceTexels, t + 2));
}

FieldVertex fieldVertexAt(uint i) {
    int t = int(i) * FIELD_VERTEX_TEXELS;
    return FieldVertex(floatTexel(vertexTexels, t), floatTexel(vertexTexels, t + 1), floatTexel(vertexTexels, t + 2),
                       texelFetch(vertexTexels, t + 3));
}

PlantModel plantModelAt(uint i) {
    int t = int(i) * PLANT_MODEL_TEXELS;
    PlantModel m;
    m.sphere = floatTexel(modelTexels, t);
    m.boxMin = floatTexel(modelTexels, t + 1);
    m.boxMax = floatTexel(modelTexels, t + 2);
    m.lod = floatTexel(modelTexels, t + 3);
    m.lists = texelFetch(modelTexels, t + 4);
    m.impostor = texelFetch(modelTexels, t + 5);
    m.impostorQuad = floatTexel(modelTexels, t + 6);
    return m;
}

// Corner `corner` (0 … OUTLINE_CORNERS − 1) of the outline billboards of atlas layer `layer`
// are drawn as (engine/field/impostor_outline.h): uv in the frame, v = 0 at the top.
vec2 outlineCorner(uint layer, uint corner) {
    vec4 pair = floatTexel(outlineTexels, int(layer * uint(IMPOSTOR_OUTLINE_TEXELS) + corner / 2u));
    return (corner & 1u) == 0u ? pair.xy : pair.zw;
}

TerrainVertex terrainVertexAt(uint i) {
    int t = int(i) * TERRAIN_VERTEX_TEXELS;
    return TerrainVertex(floatTexel(terrainTexels, t), floatTexel(terrainTexels, t + 1));
}

// Where the physics has moved joint `joint` of plant `instance` (plant
// space, before the instance transform); the identity for plants without
// a simulated skeleton.
JointPose plantJointPose(uint instance, uint joint) {
    uint skeleton = texelFetch(instanceSkeletonTexels, int(instance)).x;
    if (skeleton == NO_SKELETON) return JointPose(vec4(0.0, 0.0, 0.0, 1.0), vec4(0.0));
    return poseFromTexels(poseTexels, skeletonFromTexels(skeletonTexels, skeleton).ids.w + joint);
}

// The wind field of the physics pass (joint_physics.h windAt), for shaders
// that sway without a skeleton (impostors).
vec3 fieldWindAt(vec3 worldPos) {
    PhysicsUniforms u;
    u.gravity = vec4(0.0);
    u.wind = vec4(field.wind.x, field.wind.y, field.wind.z, field.windDetail.z);
    u.windDetail = vec4(field.windDetail.x, field.windDetail.y, 0.0, 0.0);
    u.counts = uvec4(0u);
    return windAt(worldPos, field.wind.w, u);
}

// The same vertex shaders draw the camera view and the sun's shadow maps:
// the pipeline layout's push constants say which (FIELD_PASS_*), and which
// impostors a colour draw keeps (IMPOSTOR_PART_*).
layout(push_constant) uniform FieldPushBlock {
    FieldPush fieldPush;
};

mat4 passViewProj() {
    if (fieldPush.shadowPass == FIELD_PASS_COLOR) return frame.viewProj;
    return fieldPush.shadowPass == FIELD_PASS_SHADOW ? field.sunViewProj : field.sunCacheViewProj;
}

// The plant a draw's instance stands for: gl_InstanceIndex already includes
// the command's firstInstance, i.e. the start of its (model, LOD) list.
struct VisiblePlant {
    uint index;     // into the instances (fieldInstanceAt)
    float coverage; // share of pixels drawn, for the LOD cross-fade
    bool fadeIn;
};

VisiblePlant visiblePlant(uint entryIndex) {
    uint entry = texelFetch(visibleTexels, int(entryIndex)).x;
    VisiblePlant p;
    p.index = entry & VISIBLE_INDEX_MASK;
    p.fadeIn = (entry & VISIBLE_FADE_IN_BIT) != 0u;
    p.coverage = float(entry >> VISIBLE_COVERAGE_SHIFT) / float(VISIBLE_COVERAGE_MAX);
    return p;
}

// Packs the fade into one flat varying: coverage·127, +128 when fading in.
uint packFade(VisiblePlant p) {
    return uint(round(p.coverage * 127.0)) | (p.fadeIn ? 128u : 0u);
}

mat3 yawMatrix(float yaw) {
    float c = cos(yaw), s = sin(yaw);
    return mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
}

vec3 plantToWorld(FieldInstance inst, vec3 p) {
    return inst.positionScale.xyz + yawMatrix(inst.orientation.x) * (p * inst.positionScale.w);
}

vec3 plantNormalToWorld(FieldInstance inst, vec3 n) {
    return yawMatrix(inst.orientation.x) * n;
}

// A 4×4 Bayer threshold in (0, 1) per pixel: ordered dithering for the LOD
// cross-fade.
float bayerThreshold(vec2 fragCoord) {
    const float bayer[16] = float[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    ivec2 p = ivec2(fragCoord) & 3;
    return (bayer[p.y * 4 + p.x] + 0.5) / 16.0;
}

// Dithered cross-fade: the outgoing LOD keeps the pixels whose threshold is
// below its coverage, the incoming LOD exactly the others, so together they
// cover each pixel once.
bool fadeDiscards(vec2 fragCoord, uint packedFade) {
    float coverage = float(packedFade & 127u) / 127.0;
    if (coverage >= 1.0) return false;
    float threshold = bayerThreshold(fragCoord);
    bool fadeIn = (packedFade & 128u) != 0u;
    return fadeIn ? threshold < 1.0 - coverage : threshold >= coverage;
}

// A plant mesh's fragment that no pass draws: dithered out of a fading
// plant, or outside a leaf card's outline (SURFACE_LEAF).
bool plantFragmentDiscarded(vec2 fragCoord, uint packedFade, float kind, vec2 uv) {
    return fadeDiscards(fragCoord, packedFade) || (kind > 0.5 && kind < 1.5 && leafCutOut(uv));
}

// The terrain's broadest octave of grass patches (12.5 m cells), per vertex:
// the drawn terrain has at most a few metres between samples, over which the
// octave is close to linear, so interpolating it loses nothing visible and
// saves a noise evaluation per pixel (terrain.frag adds the finer octaves).
float terrainBroadPatches(vec2 groundXz) {
    return 0.55 * valueNoise(groundXz * 0.08);
}

// Where the shadow map is read for a world position: 1.5 texels along its
// normal (turned towards the sun), in the map's clip space. The sun's
// projection is orthographic (w = 1), so this is an affine function of the
// position, which a vertex shader may pass on for the rasteriser to
// interpolate exactly (terrain.vert).
vec3 sunMapPosition(vec3 worldPos, vec3 normal) {
    vec3 offsetPos = worldPos + normal * field.viewport.z * 1.5;
    return (field.sunViewProj * vec4(offsetPos, 1.0)).xyz;
}

// Sun visibility at sunMapPosition `ndc`: 2×2 PCF of the shadow map, fully
// lit outside it or when the sun's visibility comes from elsewhere.
float sunVisibilityAt(vec3 ndc) {
    if (field.viewport.w != FIELD_SUN_SHADOW_MAP) return 1.0;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
    // One tap: the comparison sampler filters linearly, a 2×2 PCF.
    float lit = texture(shadowMap, vec3(uv, ndc.z - 0.0015));
    // Fade the shadow out toward the map's edge so its border never shows.
    float edge = smoothstep(0.0, 0.08, min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)));
    return mix(1.0, lit, edge);
}

// Sun (`visibility` of it reaching the point; for thin foliage, light
// through the back too), sky light.
vec3 shadeFieldSeen(vec3 albedo, vec3 normal, float visibility, float occlusion, float transmission) {
    float facing = dot(normal, frame.sunDirection.xyz);
    float sun = max(facing, 0.0) + transmission * max(-facing, 0.0);
    float skyWeight = 0.5 + 0.5 * normal.y;
    vec3 ambient = mix(frame.groundAlbedo.rgb * frame.skyHorizon.rgb, frame.skyZenith.rgb, skyWeight);
    return albedo * (frame.sunRadiance.rgb * sun * visibility + ambient * occlusion);
}

// The normal turned towards the sun: the side a surface lit through its
// back (foliage) is looked up on.
vec3 sunwardNormal(vec3 normal) {
    return normal * sign(dot(normal, frame.sunDirection.xyz) + 1e-4);
}

// The same with the sun's visibility from the shadow map.
vec3 shadeField(vec3 albedo, vec3 normal, vec3 worldPos, float occlusion, float transmission) {
    float visibility = sunVisibilityAt(sunMapPosition(worldPos, sunwardNormal(normal)));
    return shadeFieldSeen(albedo, normal, visibility, occlusion, transmission);
}

// The sun's visibility at a fragment of a surface the traced-sun pass saw
// (plants of the cull's mesh lists, the shadowed terrain chunks): its ray's
// result at the pixel (`fragCoord`: gl_FragCoord.xy) with ray-traced
// shadows, else the shadow map's at sunMapPosition `ndc`.
float sunVisibilityOf(vec2 fragCoord, vec3 ndc) {
    if (field.viewport.w == FIELD_SUN_RAYTRACED) return texelFetch(raytracedSun, ivec2(fragCoord), 0).r;
    return sunVisibilityAt(ndc);
}

// Where the traced-sun pass starts a fragment's ray: the point of the
// plant's rest pose (the pose the traced graph holds, so a swaying leaf is
// shadowed as at rest, never by its own resting copy), a centimetre off the
// surface on its sunward side, so the ray leaves the triangle it starts on.
vec4 raytracedSunOrigin(vec3 restPos, vec3 normal) {
    return vec4(restPos + sunwardNormal(normal) * 0.01, 1.0);
}

#endif
