#version 460
#extension GL_GOOGLE_include_directive : require
#include "canopy_bake.glsl"
#include "shared/lod_select.h"

// The canopy bake's first pass: one workgroup per leaf, its invocations
// looping over the leaf's plants. Each plant raises the cells under its
// crown to a dome (its impostor box: top, half width) and adds its albedo,
// the coverage-weighted mean of its impostor frames (the last mip of each).
// Plants too small to be drawn where the leaf turns far are left out.
layout(set = 0, binding = CANOPY_BAKE_BINDING_INSTANCES, std430) readonly buffer Instances {
    FieldInstance instances[];
};
layout(set = 0, binding = CANOPY_BAKE_BINDING_MODELS, std430) readonly buffer Models {
    PlantModel models[];
};
layout(set = 0, binding = CANOPY_BAKE_BINDING_ATLAS) uniform sampler2DArray atlasColor;

void splat(ClusterNode node, uint leaf, FieldInstance inst) {
    PlantModel model = models[inst.ids.x];
    // At the distance where a cell of this leaf is bake.params.x pixels, the
    // plant is 2·radius·params.x / cell pixels high (pixelsAtDistance).
    vec4 sphere = instanceSphere(inst, model);
    if (2.0 * sphere.w * bake.params.x / node.square.w < model.boxMax.w) return;

    float lastMip = float(textureQueryLevels(atlasColor) - 1);
    vec4 frames = vec4(0.0);
    for (uint f = 0u; f < bake.range.z; ++f)
        frames += textureLod(atlasColor, vec3(0.5, 0.5, float(model.impostor.x + f)), lastMip);
    uvec3 albedo = uvec3(clamp(frames.rgb / max(frames.a, 1e-6), 0.0, 1.0) * 255.0 + 0.5);

    float scale = inst.positionScale.w;
    float top = inst.positionScale.y + model.impostorQuad.z * scale;
    float depth = (model.impostorQuad.z - model.impostorQuad.y) * scale;
    float radius = max(model.impostorQuad.x * scale * bake.params.y, 1e-3);
    vec2 p = inst.positionScale.xz, origin = node.square.xy;
    float cell = node.square.w;
    ivec2 own = clamp(ivec2(floor((p - origin) / cell)), ivec2(0), ivec2(CLUSTER_GRID - 1));
    ivec2 lo = clamp(ivec2(floor((p - radius - origin) / cell)), ivec2(0), ivec2(CLUSTER_GRID - 1));
    ivec2 hi = clamp(ivec2(floor((p + radius - origin) / cell)), ivec2(0), ivec2(CLUSTER_GRID - 1));
    for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i) {
            float d = distance(origin + (vec2(i, j) + 0.5) * cell, p) / radius;
            if (d >= 1.0 && ivec2(i, j) != own) continue;
            uint c = bakeCell(leaf, uint(i), uint(j));
            atomicMax(cells[c], canopyHeightKey(top - 0.5 * depth * min(d * d, 1.0)));
            atomicAdd(cells[c + 1u], 1u);
            atomicAdd(cells[c + 2u], albedo.r);
            atomicAdd(cells[c + 3u], albedo.g);
            atomicAdd(cells[c + 4u], albedo.b);
        }
}

void main() {
    uint leaf = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (leaf >= bake.range.y) return;
    ClusterNode node = nodes[leaf];
    for (uint i = node.range.x + gl_LocalInvocationID.x; i < node.range.x + node.range.y; i += CULL_GROUP_SIZE)
        splat(node, leaf, instances[i]);
}
