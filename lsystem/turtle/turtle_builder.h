#pragma once
// Collects what the turtle draws into a PlantAsset: primitives, joints,
// surfaces and polygons, the bounds of all of them, and the material table.
//
// Material palette (index: name, albedo; * two-sided):
//   0 bark (brown)  1 leaf* (green)  2 petal* (pale pink)  3 pollen (yellow)
//   4 fruit (red)   5 needle* (dark green)  6 autumn* (orange)  7 deadwood (grey brown)
// Indices past 7 repeat the palette (8 is "bark 8", ...). The table always
// holds the whole palette, and up to the largest index a primitive uses.
// A material used by a surface or a polygon is two-sided.

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsystem/turtle/plant_asset.h"

namespace lsys {

class SurfaceLibrary;

const std::vector<Material>& defaultPalette();

// The material table of a plant drawn with `look` whose primitives use the
// indices below `used`: the look's palette (else defaultPalette()) as
// PlantAssetBuilder describes it, `twoSided[i]` making material i two-sided
// (one a surface or polygon used).
std::vector<Material> materialTable(const PlantLook& look, size_t used, const std::vector<bool>& twoSided);

// Extends `bounds` by a disc of `radius` about `centre` facing the unit
// `unitNormal`: a segment's end (the two end discs of a frustum bound it exactly).
void extendByDisc(Bounds& bounds, glm::vec3 centre, glm::vec3 unitNormal, float radius);
// The box of a set of points (a surface's vertices in its own space).
Bounds boundsOfPoints(const std::vector<glm::vec3>& points);

// The surface a plant of `look` draws for `name`: the look's own (a vlab
// object's .s files) before the library's. Throws SurfaceError when neither
// has it.
const SurfaceMesh& surfaceOfLook(const PlantLook& look, const SurfaceLibrary& surfaces, const std::string& name);

class PlantAssetBuilder {
public:
    // A look's palette replaces defaultPalette() (indices past its end
    // become its first entry's); its surfaces come before the library's.
    explicit PlantAssetBuilder(const SurfaceLibrary& surfaces, PlantLook look = {})
        : surfaces_(surfaces), look_(std::move(look)) {}

    // A segment and its joint; returns the joint's index.
    int32_t addSegment(const Frame& base, float length, float startRadius, float endRadius, uint32_t material,
                       int32_t parentJoint, float stiffness);
    void addSphere(const Frame& centre, float radius, uint32_t material, int32_t joint);
    // Throws SurfaceError when the library has no surface of that name.
    // Returns the surface's SurfaceMesh::endPoint, in its own space.
    glm::vec3 addSurface(const std::string& name, const Frame& frame, float scale, uint32_t material, int32_t joint);
    void addPolygon(const Frame& start, std::vector<glm::vec3> outline, uint32_t material, int32_t joint);

    // The asset with its material table; the builder is left empty.
    PlantAsset finish();

private:
    void markTwoSided(uint32_t material);

    const SurfaceLibrary& surfaces_;
    PlantLook look_;
    PlantAsset asset_;
    std::unordered_map<std::string, uint32_t> surfaceIndex_; // name -> asset_.surfaces index
    std::vector<Bounds> surfaceBounds_;                      // local bounds per asset_.surfaces entry
    std::vector<bool> twoSided_;                             // per material index used by a surface or polygon
};

} // namespace lsys
