#pragma once
// cpfg's surface files (.s): bicubic Bézier patches with a contact point, an
// end point, a heading and an up vector and a size (ABOP §5.1's predefined
// surfaces), tessellated as cpfg tessellates them and placed in the space
// lsystem/turtle/surfaces.h defines (grows along +Y, faces +Z), so `~l` draws them.
//
// As cpfg's patches.c reads them (read_surface): every control point is
// moved by minus the contact point, scaled by the view file's size over the
// file's SIZE, and rotated by the matrix whose columns are the file's left
// (heading x up), heading and up; cpfg then draws local x along the turtle's
// left L, y along H and z along its U. cpfg's U is L x H, the opposite of
// lsystem/turtle/turtle.h's, so x and z change sign here (a half turn about Y).
// Each patch becomes an (s + 1) x (t + 1) grid of points (s runs down the
// rows of control points, t along them), with cpfg's normals: the cross
// product of the tangents, its four corners blended with their neighbours,
// and the normals along edges shared with a neighbouring patch averaged.

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/common/error.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys::vlab {

struct SurfaceReadResult {
    SurfaceMesh mesh; // named `name`
    // Where cpfg moves the turtle after drawing the surface (patches.c,
    // determine_end_point): the file's END POINT in the mesh's space, for
    // ~name(1); ~name(s) moves s times as far.
    glm::vec3 endPoint{0.0f};
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return diagnostics.empty(); }
};

// `scale` and the precisions come from the view file's "surface:" line
// (0: the file's own precision). As in cpfg, a scale of 0 or less is 1, a
// missing t precision is the file's s precision (sic: patches.c,
// determine_transform), and precisions are kept within 1..10.
SurfaceReadResult readSurfaceFile(const std::filesystem::path& path, const std::string& name, float scale = 1.0f,
                                  int sPrecision = 0, int tPrecision = 0);

// cpfg's limits (patch.h PATCHES, patches.c S_COUNT and T_COUNT).
inline constexpr int kMaxSurfacePatches = 64;
inline constexpr int kMaxSurfacePrecision = 10;

} // namespace lsys::vlab
