// Which plants cast into the sun's shadow map, and which of those the cached
// map of static casters holds (engine/field/shadow_casters.h), shared by
// shaders/shadow_cull.comp and pf::shadowCastersOnCpu like lod_select.h.
//
// What casts (docs/FIELD.md, "The sun's shadows"): a plant the camera sees
// at LOD0 casts its full mesh; every other plant casts its impostor's
// shadow frame, the plant seen from the sun (docs/IMPOSTORS.md, "Shadow
// frames"), whatever LOD the camera draws it at. A reduced tree's shadow is
// its silhouette toward the sun blurred over a few texels of the map
// (Reeves, Salesin & Cook 1987: percentage-closer filtering averages the
// map's depth tests over its kernel, so detail finer than the kernel does
// not show), which the shadow frame baked from its full mesh holds; its
// leaf cards, each shaded under the cut-out test, cost a software
// rasteriser many times its one textured quad.
//
// The frame's map is the cache's window with the other casters drawn on top,
// so each caster must be drawn exactly once, in the form the frame's own
// camera gives it: the cache holds a plant only when every camera it serves
// sees that plant beyond LOD0 and large enough to draw, so it casts as an
// impostor for all of them; every other caster is decided by the frame
// itself. A frame therefore shows the same casters whether the cache was
// drawn for it or for a camera some metres away. The impostor's shadow
// depends on the sun alone (not on the camera), so the cache's copy is the
// frame's texel for texel.
#ifndef PLANTFIELD_SHADERS_SHADOW_SELECT_H
#define PLANTFIELD_SHADERS_SHADOW_SELECT_H

#include "lod_select.h"

#ifdef __cplusplus
namespace gpu {
#define SHADOW_SELECT_FN inline
#else
#define SHADOW_SELECT_FN
#endif

// shadowCasterLod: the plant casts nothing in this pass.
#define SHADOW_NOT_CAST 0xFFFFFFFFu

// The LOD a plant casts from at `pixels` on the camera's screen: the full
// mesh where the camera sees it at LOD0, its impostor everywhere else (a
// forced LOD casts as forced). Casting impostors also lets the cache hold
// every plant no camera it serves sees at LOD0.
SHADOW_SELECT_FN uint shadowLodForPixels(float pixels, PlantModel model, uint forcedLod) {
    if (forcedLod != LOD_NOT_FORCED) return forcedLod;
    return lodForPixels(pixels, model.lod.x, model.lod.y) == LOD_FULL ? uint(LOD_FULL) : uint(LOD_IMPOSTOR);
}

// True when the plant casts as an impostor large enough to draw for every
// camera the cache serves: within cacheCamera.w metres of cacheCamera.xyz (so
// at most that much nearer or farther) with between cachePixels.x and
// cachePixels.y pixels per metre at one metre.
SHADOW_SELECT_FN bool heldByShadowCache(vec4 sphere, PlantModel model, vec4 cacheCamera, vec4 cachePixels,
                                        uint forcedLod) {
    float d = distance(vec3(cacheCamera), vec3(sphere));
    float most = pixelsAtDistance(sphere.w, cachePixels.y, d - cacheCamera.w);
    float fewest = pixelsAtDistance(sphere.w, cachePixels.x, d + cacheCamera.w);
    return shadowLodForPixels(most, model, forcedLod) == LOD_IMPOSTOR && largeEnoughToDraw(fewest, model, forcedLod);
}

// True when the sphere's shadow volume, the sphere swept away from the sun
// (`towardSun`), lies wholly outside the plane: its centre is farther than
// its radius outside, and moving away from the sun never brings it closer.
SHADOW_SELECT_FN bool shadowOutsidePlane(vec4 sphere, vec3 towardSun, vec4 plane) {
    return dot(vec3(plane), vec3(sphere)) + plane.w < -sphere.w && dot(vec3(plane), towardSun) >= 0.0f;
}

// True unless the sphere's shadow volume lies outside one of the camera's
// frustum planes: then it darkens nothing the camera sees (a conservative
// test, like sphereInFrustum).
SHADOW_SELECT_FN bool shadowMayFallInView(vec4 sphere, ShadowCullUniforms u) {
    vec3 l = vec3(u.sun);
    return !(shadowOutsidePlane(sphere, l, u.view[0]) || shadowOutsidePlane(sphere, l, u.view[1]) ||
             shadowOutsidePlane(sphere, l, u.view[2]) || shadowOutsidePlane(sphere, l, u.view[3]) ||
             shadowOutsidePlane(sphere, l, u.view[4]) || shadowOutsidePlane(sphere, l, u.view[5]));
}

// The LOD list an instance casts from in this pass (u.counts.w), or
// SHADOW_NOT_CAST. Casters are the plants whose sphere meets the sun's box;
// the cache holds them in view of the camera or not, since it serves
// cameras turned other ways, while the frame draws those whose shadow may
// fall in its view, at shadowLodForPixels of the camera's target LOD (no
// hysteresis and no fade, which depend on earlier frames). A plant the
// cache holds and whose shadow misses the view is in the frame's map or not
// depending on where the cache was drawn, but never in what the camera sees.
SHADOW_SELECT_FN uint shadowCasterLod(FieldInstance inst, PlantModel model, ShadowCullUniforms u) {
    vec4 sphere = instanceSphere(inst, model);
    if (!sphereInFrustum(sphere, u.box[0], u.box[1], u.box[2], u.box[3], u.box[4], u.box[5])) return SHADOW_NOT_CAST;
    bool cached = heldByShadowCache(sphere, model, u.cacheCamera, u.cachePixels, u.counts.z);
    if (u.counts.w == SHADOW_CULL_CACHE) return cached ? uint(LOD_IMPOSTOR) : SHADOW_NOT_CAST;
    if (cached || !shadowMayFallInView(sphere, u)) return SHADOW_NOT_CAST;
    float pixels = projectedPixels(sphere, u.camera);
    if (!largeEnoughToDraw(pixels, model, u.counts.z)) return SHADOW_NOT_CAST;
    return shadowLodForPixels(pixels, model, u.counts.z);
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef SHADOW_SELECT_FN

#endif
