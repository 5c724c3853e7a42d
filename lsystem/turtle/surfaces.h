#pragma once
// Predefined surfaces for the turtle's ~name(s) (ABOP ch. 5): the built-in
// procedural `leaf` and `petal`, and meshes read from glTF files.
//
// Every surface is in its own space with the axes of a Frame: it grows from
// the origin along local +Y (the turtle's heading) to about y = 1, spreads
// along local X (the turtle's left/right) and faces local +Z (up), so
// ~leaf(s) draws a leaf of length s on the turtle's L-H plane.

#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// An unknown surface name or a mesh file that cannot be read.
struct SurfaceError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Resolves surface names: the built-ins first, then <dir>/<name>.gltf and
// <dir>/<name>.glb in each directory in order. A file is read once; later
// lookups return the same mesh. Safe to share between threads.
class SurfaceLibrary {
public:
    explicit SurfaceLibrary(std::vector<std::filesystem::path> meshDirectories = {});

    // Throws SurfaceError naming the surface and every path tried.
    const SurfaceMesh& surface(const std::string& name) const;

    const std::vector<std::filesystem::path>& meshDirectories() const { return directories_; }

private:
    std::vector<std::filesystem::path> directories_;
    mutable std::mutex mutex_;
    mutable std::map<std::string, SurfaceMesh> loaded_;
};

// The `meshes` folders beside a plant file or any folder above it, nearest
// first: data/plants/dialects/x.lsys finds data/meshes.
std::vector<std::filesystem::path> meshDirectoriesFor(const std::filesystem::path& plantFile);

// The built-in procedural surfaces.
SurfaceMesh leafSurface();  // an elliptic blade 1 long, 0.5 wide, its midrib slightly folded
SurfaceMesh petalSurface(); // an obovate petal 1 long, widest near the tip, cupped upwards

// The triangles of the first mesh in a .gltf or .glb file, in the mesh's own
// space (node transforms are not applied), named `name`. Normals and uvs are
// kept when every primitive has them. Throws SurfaceError naming the file.
SurfaceMesh loadSurfaceFile(const std::filesystem::path& file, const std::string& name);

} // namespace lsys
