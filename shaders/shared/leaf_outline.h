// The outline of a leaf card, shared by GLSL (plant_surface.glsl leafShape,
// which cuts the card) and C++ (lsystem/mesh/drawn_mesh.cpp, which meshes the same
// outline for exports), so what is exported is what is drawn. A card's uv is
// [0,1]²: v runs from the petiole (v = 0) to the tip (v = 1), u across, the
// midrib at u = 0.5. The macros take a float; in C++ the functions below
// evaluate them (in double precision).
#ifndef PLANTFIELD_SHADERS_LEAF_OUTLINE_H
#define PLANTFIELD_SHADERS_LEAF_OUTLINE_H

// Half the blade's width at v, as a fraction of the card's width: a pointed
// ovate blade, widest a little below the middle.
#define LEAF_HALF_WIDTH(v) (0.48 * pow(sin(3.14159265 * pow((v), 0.8)), 0.9) * (1.0 - 0.25 * (v)))
// The slightly serrated edge added to the half width (about 11 teeth a side).
#define LEAF_SERRATION(v) (0.018 * sin((v)*70.0))
// The petiole: a strip of this half width along the midrib below this v.
#define LEAF_PETIOLE_LENGTH 0.08
#define LEAF_PETIOLE_HALF_WIDTH 0.025

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
namespace leaf_outline {

// LEAF_HALF_WIDTH at v ∈ [0, 1] (clamped), never negative.
inline double halfWidth(double v) {
    using std::pow;
    using std::sin;
    v = std::clamp(v, 0.0, 1.0);
    return std::max(LEAF_HALF_WIDTH(v), 0.0);
}

// The shader's leafShape(uv): > 0 inside the leaf.
inline double shape(double u, double v) {
    using std::sin;
    v = std::clamp(v, 0.0, 1.0);
    const double x = std::abs(u - 0.5);
    const double petiole = (v < LEAF_PETIOLE_LENGTH && x < LEAF_PETIOLE_HALF_WIDTH) ? 1.0 : 0.0;
    return std::max(halfWidth(v) + LEAF_SERRATION(v) - x, petiole * 0.01);
}

} // namespace leaf_outline
#endif

#endif
