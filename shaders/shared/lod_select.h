// The cull + LOD decision of one field instance (docs/CULLING.md), shared by
// shaders/cull.comp and pf::cullOnCpu so both make the same choice with the
// same float operations. GLSL and C++ (namespace gpu, glm) read this file;
// float literals carry an f suffix so C++ does not widen to double.
#ifndef PLANTFIELD_SHADERS_LOD_SELECT_H
#define PLANTFIELD_SHADERS_LOD_SELECT_H

#include "field_layouts.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec3 = glm::vec3;
using mat3 = glm::mat3;
using glm::ceil;
using glm::cos;
using glm::distance;
using glm::dot;
using glm::max;
using glm::min;
using glm::sin;
#define LOD_SELECT_FN inline
#else
#define LOD_SELECT_FN
#endif

// No forced LOD in CullUniforms::counts.z.
#define LOD_NOT_FORCED 0xFFFFFFFFu

// The state word: current LOD, the LOD it fades from, fade progress.
LOD_SELECT_FN uint lodStateCurrent(uint state) { return state & LOD_STATE_LOD_MASK; }
LOD_SELECT_FN uint lodStateFrom(uint state) { return (state >> LOD_STATE_LOD_BITS) & LOD_STATE_LOD_MASK; }
LOD_SELECT_FN uint lodStateProgress(uint state) { return (state >> LOD_STATE_PROGRESS_SHIFT) & 255u; }
LOD_SELECT_FN uint lodStatePack(uint current, uint from, uint progress) {
    return current | (from << LOD_STATE_LOD_BITS) | (progress << LOD_STATE_PROGRESS_SHIFT);
}

// World-space bounding sphere of an instance: xyz centre, w radius. The yaw
// rotation is field_common.glsl's yawMatrix.
LOD_SELECT_FN vec4 instanceSphere(FieldInstance inst, PlantModel model) {
    float c = cos(inst.orientation.x), s = sin(inst.orientation.x);
    mat3 yaw = mat3(c, 0.0f, -s, 0.0f, 1.0f, 0.0f, s, 0.0f, c);
    float scale = inst.positionScale.w;
    vec3 centre = vec3(inst.positionScale) + yaw * (vec3(model.sphere) * scale);
    return vec4(centre, model.sphere.w * scale);
}

// False when the sphere lies entirely outside one of the frustum planes.
LOD_SELECT_FN bool sphereInFrustum(vec4 sphere, vec4 plane0, vec4 plane1, vec4 plane2, vec4 plane3, vec4 plane4,
                                   vec4 plane5) {
    vec3 c = vec3(sphere);
    float r = -sphere.w;
    return dot(vec3(plane0), c) + plane0.w >= r && dot(vec3(plane1), c) + plane1.w >= r &&
           dot(vec3(plane2), c) + plane2.w >= r && dot(vec3(plane3), c) + plane3.w >= r &&
           dot(vec3(plane4), c) + plane4.w >= r && dot(vec3(plane5), c) + plane5.w >= r;
}

// Projected height in pixels of a sphere of `radius` at `distance` from a
// camera of `pixelsPerMetre` pixels per metre at one metre of distance.
LOD_SELECT_FN float pixelsAtDistance(float radius, float pixelsPerMetre, float distance) {
    return 2.0f * radius * pixelsPerMetre / max(distance, 0.001f);
}

// Projected height of the sphere in pixels; camera.w is pixels per metre at
// one metre of distance.
LOD_SELECT_FN float projectedPixels(vec4 sphere, vec4 camera) {
    return pixelsAtDistance(sphere.w, camera.w, distance(vec3(camera), vec3(sphere)));
}

// Contribution culling: a plant smaller on screen than model.boxMax.w pixels
// adds nothing but triangles (far grass), so it is treated as outside the
// view. A forced LOD draws everything in view.
LOD_SELECT_FN bool largeEnoughToDraw(float pixels, PlantModel model, uint forcedLod) {
    return forcedLod != LOD_NOT_FORCED || pixels >= model.boxMax.w;
}

// LOD for a projected height against two thresholds (between 0|1 and 1|2).
LOD_SELECT_FN uint lodForPixels(float pixels, float threshold01, float threshold12) {
    return pixels >= threshold01 ? 0u : (pixels >= threshold12 ? 1u : 2u);
}

// LOD with hysteresis: a boundary the plant would cross toward coarser LODs
// sits at T·(1−h), one it would cross toward finer LODs at T·(1+h).
LOD_SELECT_FN uint lodWithHysteresis(float pixels, uint previous, vec4 lod) {
    float coarser = 1.0f - lod.z, finer = 1.0f + lod.z;
    return lodForPixels(pixels, lod.x * (previous == 0u ? coarser : finer), lod.y * (previous <= 1u ? coarser : finer));
}

// The next state word of an instance. `inside`: the sphere meets the
// frustum. A culled plant keeps its LOD (the target on the first frame or
// the forced LOD) and is settled.
LOD_SELECT_FN uint nextLodState(uint state, bool inside, float pixels, vec4 lod, uint forcedLod, bool firstFrame,
                                float deltaSeconds) {
    if (forcedLod != LOD_NOT_FORCED) return lodStatePack(forcedLod, forcedLod, LOD_STATE_SETTLED);
    uint previous = lodStateCurrent(state);
    if (firstFrame) {
        uint target = lodForPixels(pixels, lod.x, lod.y);
        return lodStatePack(target, target, LOD_STATE_SETTLED);
    }
    if (!inside) return lodStatePack(previous, previous, LOD_STATE_SETTLED);
    uint current = lodWithHysteresis(pixels, previous, lod);
    uint from = lodStateFrom(state);
    uint progress = lodStateProgress(state);
    if (current != previous) {
        from = previous;
        progress = 0u;
    }
    // ceil: any time that passes moves the fade on, so it never outlasts lod.w.
    float step = lod.w > 0.0f ? ceil(255.0f * deltaSeconds / lod.w) : 255.0f;
    progress = uint(min(float(progress) + step, 255.0f));
    return lodStatePack(current, from, progress);
}

// Coverage (0..VISIBLE_COVERAGE_MAX) of the incoming LOD at a fade progress;
// the outgoing LOD gets the rest, so the two always sum to the maximum.
LOD_SELECT_FN uint fadeInCoverage(uint progress) { return (progress * VISIBLE_COVERAGE_MAX + 127u) / 255u; }

LOD_SELECT_FN uint visibleEntry(uint index, uint flags, uint coverage) {
    return index | flags | (coverage << VISIBLE_COVERAGE_SHIFT);
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef LOD_SELECT_FN

#endif
