// Surface appearance of plant meshes, shared by the field's plant shaders
// and the impostor baker so an impostor shows exactly what LOD0 shows.
// Needs no bindings.
#ifndef PLANT_SURFACE_GLSL
#define PLANT_SURFACE_GLSL
#include "shared/field_layouts.h"
#include "shared/leaf_outline.h"

float surfaceHash(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

// Coverage of a leaf card at uv ∈ [0,1]²: a pointed ovate blade along v from
// the petiole (v = 0) to the tip (v = 1), with a slightly serrated edge
// (leaf_outline.h, whose outline the exports mesh). Returns a signed
// distance-like value: > 0 inside.
float leafShape(vec2 uv) {
    float v = clamp(uv.y, 0.0, 1.0);
    float halfWidth = LEAF_HALF_WIDTH(v);
    float serration = LEAF_SERRATION(v);
    float x = abs(uv.x - 0.5);
    float petiole = (v < LEAF_PETIOLE_LENGTH && x < LEAF_PETIOLE_HALF_WIDTH) ? 1.0 : 0.0;
    return max(halfWidth + serration - x, petiole * 0.01);
}

// Alpha-test threshold shared by every pass that draws leaf cards.
bool leafCutOut(vec2 uv) { return leafShape(uv) <= 0.0; }

// Albedo with a little variation: bark streaks along v, a midrib and lighter
// tips on leaves, slight darkening toward blade bases.
vec3 surfaceAlbedo(vec3 albedo, float kind, vec2 uv) {
    if (kind < 0.5) {
        float streak = surfaceHash(vec2(floor(uv.x * 12.0), floor(uv.y * 6.0)));
        return albedo * mix(0.75, 1.1, streak);
    }
    if (kind < 1.5) {
        float midrib = 1.0 - 0.25 * smoothstep(0.03, 0.0, abs(uv.x - 0.5));
        return albedo * mix(0.85, 1.15, uv.y) * midrib;
    }
    return albedo * mix(0.7, 1.1, clamp(uv.y, 0.0, 1.0));
}

// Thin foliage lets light through: a share of the sun reaches the back face.
const float kFoliageTransmission = 0.35;

#endif
