// Terrain heightfields: a square grid of heights centred on the origin, y up.
// Built from seeded fBm noise or a greyscale PNG; sampled bilinearly.
#pragma once

#include "lsystem/common/memory_budget.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pf {

struct Heightfield {
    uint32_t resolution = 0;    // samples along each side, at least 2
    float size = 0;             // side length in metres; samples span [-size/2, size/2] in x and z
    std::vector<float> heights; // resolution² heights in metres, row by row: heights[iz * resolution + ix]

    float spacing() const { return size / float(resolution - 1); }
    // World x of sample column i (or z of sample row i).
    float coordinate(uint32_t i) const { return -0.5f * size + float(i) * spacing(); }
    float height(uint32_t ix, uint32_t iz) const { return heights[size_t(iz) * resolution + ix]; }
};

// Fractal Brownian motion of 2D gradient noise: octave i has frequency
// frequency·lacunarityⁱ and amplitude amplitude·gainⁱ. Heights stay within
// ±amplitude·(1 + gain + … + gain^(octaves-1))·√½, the bound of gradient noise.
struct NoiseTerrainSettings {
    uint32_t resolution = 257;
    float size = 512; // metres
    uint64_t seed = 0;
    uint32_t octaves = 5;
    float frequency = 1.0f / 200.0f; // cycles per metre of the first octave: hills about 200 m apart
    float amplitude = 16;            // metres
    float lacunarity = 2;
    float gain = 0.5f;
    lsys::MemoryBudget memory = lsys::machineMemoryBudget(); // heightfieldBytes(resolution) must fit
};

// What a heightfield of `resolution` samples a side costs while it is built:
// its heights, and those of the one it replaces (a terrain grown to a plant
// count is built again larger), saturating.
uint64_t heightfieldBytes(uint32_t resolution);

// Same settings ⇒ same heights, bit for bit. Throws on a resolution below 2 or
// a size that is not positive, and lsys::MemoryBudgetError (stage "terrain")
// when heightfieldBytes is past the budget, before allocating.
Heightfield makeNoiseTerrain(const NoiseTerrainSettings& settings);

// A square greyscale PNG, one sample a pixel: grey level g maps to height
// g/255·heightScale; image column → +x, image row (top first) → +z. Throws,
// naming the file, when it cannot be read, is not square, is smaller than
// 2×2, or has a pixel whose red, green and blue differ.
Heightfield loadImageTerrain(const std::string& path, float size, float heightScale,
                             const lsys::MemoryBudget& memory = lsys::machineMemoryBudget());

// Bilinear between the four surrounding samples; points outside the square
// take the height of the nearest edge.
float heightAt(const Heightfield& terrain, float x, float z);
// Unit upward normal from central differences one sample apart (one-sided at
// the edges), so a plane gives its exact normal.
glm::vec3 normalAt(const Heightfield& terrain, float x, float z);
// Angle between the normal and +y: 0 on flat ground, 90 on a wall.
float slopeDegreesAt(const Heightfield& terrain, float x, float z);

// One vertex a sample and two counter-clockwise (seen from above) triangles a
// cell: resolution² vertices, 6·(resolution-1)² indices.
struct TerrainMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> indices;
};
TerrainMesh makeTerrainMesh(const Heightfield& terrain);

} // namespace pf
