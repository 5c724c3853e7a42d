// Bindings and helpers of the field's draw passes (plants, impostors,
// terrain, shadows): one descriptor set, layouts from field_layouts.h.
#ifndef FIELD_COMMON_GLSL
#define FIELD_COMMON_GLSL
#define FIELD_FRAME
#include "common.glsl"
#include "plant_surface.glsl"
#include "joint_physics.h"

layout(set = 0, binding = FIELD_BINDING_INSTANCES, std430) readonly buffer Instances {
    FieldInstance instances[];
};
layout(set = 0, binding = FIELD_BINDING_VISIBLE, std430) readonly buffer Visible {
    uint visible[];
};
layout(set = 0, binding = FIELD_BINDING_VERTICES, std430) readonly buffer Vertices {
    FieldVertex vertices[];
};
layout(set = 0, binding = FIELD_BINDING_MODELS, std430) readonly buffer Models {
    PlantModel models[];
};
layout(set = 0, binding = FIELD_BINDING_ATLAS_COLOR) uniform sampler2DArray atlasColor;
layout(set = 0, binding = FIELD_BINDING_ATLAS_NORMAL) uniform sampler2DArray atlasNormal;
layout(set = 0, binding = FIELD_BINDING_SHADOW) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = FIELD_BINDING_TERRAIN, std430) readonly buffer Terrain {
    TerrainVertex terrain[];
};

layout(set = 0, binding = FIELD_BINDING_SKELETONS, std430) readonly buffer Skeletons {
    Skeleton skeletons[];
};
layout(set = 0, binding = FIELD_BINDING_POSES, std430) readonly buffer Poses {
    JointPose poses[];
};
layout(set = 0, binding = FIELD_BINDING_INSTANCE_SKELETON, std430) readonly buffer InstanceSkeletons {
    uint instanceSkeleton[];
};

// Where the physics has moved joint `joint` of plant `instance` (plant
// space, before the instance transform); the identity for plants without
// a simulated skeleton.
JointPose plantJointPose(uint instance, uint joint) {
    uint skeleton = instanceSkeleton[instance];
    if (skeleton == NO_SKELETON) return JointPose(vec4(0.0, 0.0, 0.0, 1.0), vec4(0.0));
    return poses[skeletons[skeleton].ids.w + joint];
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

// The same vertex shaders draw the camera view and the sun's shadow map:
// the pipeline layout's push constant says which.
layout(push_constant) uniform FieldPush {
    uint shadowPass; // 1: depth from the sun
} fieldPush;

mat4 passViewProj() {
    return fieldPush.shadowPass != 0u ? field.sunViewProj : frame.viewProj;
}

// The plant a draw's instance stands for: gl_InstanceIndex already includes
// the command's firstInstance, i.e. the start of its (model, LOD) list.
struct VisiblePlant {
    uint index;     // into instances[]
    float coverage; // share of pixels drawn, for the LOD cross-fade
    bool fadeIn;
};

VisiblePlant visiblePlant(uint entryIndex) {
    uint entry = visible[entryIndex];
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

// Fog per vertex (rgb: the sky seen along the view ray, a: amount): it
// changes slowly across a plant or a terrain cell, and the sky term is the
// most expensive part of shading a far, small plant.
vec4 vertexFog(vec3 worldPos) {
    vec3 toPoint = worldPos - frame.cameraPosition.xyz;
    float amount = 1.0 - exp(-length(toPoint) * frame.fog.x);
    return vec4(skyRadiance(normalize(vec3(toPoint.x, max(toPoint.y, 0.0), toPoint.z))), amount);
}

vec3 applyVertexFog(vec3 color, vec4 fog) {
    return mix(color, fog.rgb, fog.a);
}

// Sun visibility at a world position: 2×2 PCF of the shadow map, fully lit
// outside it or when shadows are off.
float sunVisibility(vec3 worldPos, vec3 normal) {
    if (field.viewport.w < 0.5) return 1.0;
    vec3 offsetPos = worldPos + normal * field.viewport.z * 1.5;
    vec4 clip = field.sunViewProj * vec4(offsetPos, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
    // One tap: the comparison sampler filters linearly, a 2×2 PCF.
    float lit = texture(shadowMap, vec3(uv, ndc.z - 0.0015));
    // Fade the shadow out toward the map's edge so its border never shows.
    float edge = smoothstep(0.0, 0.08, min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)));
    return mix(1.0, lit, edge);
}

// Sun (with shadow and, for thin foliage, light through the back), sky light.
vec3 shadeField(vec3 albedo, vec3 normal, vec3 worldPos, float occlusion, float transmission) {
    vec3 l = frame.sunDirection.xyz;
    float facing = dot(normal, l);
    float sun = max(facing, 0.0) + transmission * max(-facing, 0.0);
    float visibility = sunVisibility(worldPos, normal * sign(facing + 1e-4));
    float skyWeight = 0.5 + 0.5 * normal.y;
    vec3 ambient = mix(frame.groundAlbedo.rgb * frame.skyHorizon.rgb, frame.skyZenith.rgb, skyWeight);
    return albedo * (frame.sunRadiance.rgb * sun * visibility + ambient * occlusion);
}

#endif
