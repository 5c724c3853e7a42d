#include "engine/scene/terrain.h"

#include "engine/image/image.h"
#include "lsystem/common/random.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pf {

namespace {

// Eight unit gradients with exact coordinates, so the noise is the same on
// every platform (no sin/cos of hashed angles).
constexpr float kDiagonal = 0.70710678f;
constexpr float kGradients[8][2] = {{1, 0},
                                    {-1, 0},
                                    {0, 1},
                                    {0, -1},
                                    {kDiagonal, kDiagonal},
                                    {-kDiagonal, kDiagonal},
                                    {kDiagonal, -kDiagonal},
                                    {-kDiagonal, -kDiagonal}};

float quinticFade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// Contribution of lattice corner (ix, iz) at offset (dx, dz) from it; the
// gradient comes from a hash of the corner, not from a shared table or RNG.
float cornerValue(uint64_t key, int32_t ix, int32_t iz, float dx, float dz) {
    const uint64_t corner = uint64_t(uint32_t(ix)) | uint64_t(uint32_t(iz)) << 32;
    const float* g = kGradients[lsys::splitmix64(key ^ corner) & 7];
    return g[0] * dx + g[1] * dz;
}

// Perlin's gradient noise in 2D; within ±√½.
float gradientNoise(uint64_t key, float x, float z) {
    const float fx = std::floor(x), fz = std::floor(z);
    const int32_t ix = int32_t(fx), iz = int32_t(fz);
    const float dx = x - fx, dz = z - fz;
    const float u = quinticFade(dx), v = quinticFade(dz);
    const float bottom = std::lerp(cornerValue(key, ix, iz, dx, dz), cornerValue(key, ix + 1, iz, dx - 1, dz), u);
    const float top =
        std::lerp(cornerValue(key, ix, iz + 1, dx, dz - 1), cornerValue(key, ix + 1, iz + 1, dx - 1, dz - 1), u);
    return std::lerp(bottom, top, v);
}

Heightfield emptyHeightfield(uint32_t resolution, float size) {
    return {resolution, size, std::vector<float>(size_t(resolution) * resolution)};
}

// Heights at the two ends of a central difference along one axis, clamped to
// the square so the edges use a one-sided difference over the true distance.
float slopeAlong(const Heightfield& terrain, float x, float z, float stepX, float stepZ) {
    const float half = 0.5f * terrain.size;
    const float x0 = std::clamp(x - stepX, -half, half), x1 = std::clamp(x + stepX, -half, half);
    const float z0 = std::clamp(z - stepZ, -half, half), z1 = std::clamp(z + stepZ, -half, half);
    const float run = (x1 - x0) + (z1 - z0);
    return run > 0 ? (heightAt(terrain, x1, z1) - heightAt(terrain, x0, z0)) / run : 0.0f;
}

} // namespace

uint64_t heightfieldBytes(uint32_t resolution) {
    return lsys::bytesTimes(uint64_t(resolution) * resolution, 2 * sizeof(float));
}

Heightfield makeNoiseTerrain(const NoiseTerrainSettings& s) {
    if (s.resolution < 2) throw std::invalid_argument("noise terrain: resolution must be at least 2");
    if (!(s.size > 0)) throw std::invalid_argument("noise terrain: size must be positive");
    lsys::need(s.memory, "terrain", heightfieldBytes(s.resolution));
    Heightfield terrain = emptyHeightfield(s.resolution, s.size);
    for (uint32_t octave = 0; octave < s.octaves; ++octave) {
        const uint64_t key = lsys::splitmix64(lsys::splitmix64(s.seed) ^ octave);
        // A per-octave offset keeps the lattice points (where gradient noise
        // is zero) of different octaves from lining up at the origin.
        const float offsetX = float(key >> 40) * 0x1.0p-16f, offsetZ = float((key >> 16) & 0xFFFFFF) * 0x1.0p-16f;
        const float frequency = s.frequency * std::pow(s.lacunarity, float(octave));
        const float amplitude = s.amplitude * std::pow(s.gain, float(octave));
        for (uint32_t iz = 0; iz < s.resolution; ++iz)
            for (uint32_t ix = 0; ix < s.resolution; ++ix)
                terrain.heights[size_t(iz) * s.resolution + ix] +=
                    amplitude * gradientNoise(key, terrain.coordinate(ix) * frequency + offsetX,
                                              terrain.coordinate(iz) * frequency + offsetZ);
    }
    return terrain;
}

Heightfield loadImageTerrain(const std::string& path, float size, float heightScale, const lsys::MemoryBudget& memory) {
    const RgbaImage image = readPng(path, memory);
    const std::string where = "terrain image '" + path + "'";
    if (image.width != image.height)
        throw std::runtime_error(where + " must be square, not " + std::to_string(image.width) + "x" +
                                 std::to_string(image.height));
    if (image.width < 2) throw std::runtime_error(where + " must be at least 2x2 pixels");
    if (!(size > 0)) throw std::invalid_argument(where + ": size must be positive");
    lsys::need(memory, "terrain", heightfieldBytes(image.width));
    Heightfield terrain = emptyHeightfield(image.width, size);
    for (size_t i = 0; i < terrain.heights.size(); ++i) {
        const uint8_t* rgb = &image.pixels[i * 4];
        if (rgb[0] != rgb[1] || rgb[1] != rgb[2])
            throw std::runtime_error(where + " is not greyscale: pixel (" + std::to_string(i % image.width) + ", " +
                                     std::to_string(i / image.width) + ") has red, green and blue " +
                                     std::to_string(rgb[0]) + ", " + std::to_string(rgb[1]) + ", " +
                                     std::to_string(rgb[2]));
        terrain.heights[i] = float(rgb[0]) / 255.0f * heightScale;
    }
    return terrain;
}

float heightAt(const Heightfield& terrain, float x, float z) {
    const float last = float(terrain.resolution - 1);
    const float gx = std::clamp((x + 0.5f * terrain.size) / terrain.spacing(), 0.0f, last);
    const float gz = std::clamp((z + 0.5f * terrain.size) / terrain.spacing(), 0.0f, last);
    // The cell's lower corner stays below the last sample so the far edge
    // interpolates inside the last cell with weight 1.
    const uint32_t ix = std::min(uint32_t(gx), terrain.resolution - 2);
    const uint32_t iz = std::min(uint32_t(gz), terrain.resolution - 2);
    const float u = gx - float(ix), v = gz - float(iz);
    const float near = std::lerp(terrain.height(ix, iz), terrain.height(ix + 1, iz), u);
    const float far = std::lerp(terrain.height(ix, iz + 1), terrain.height(ix + 1, iz + 1), u);
    return std::lerp(near, far, v);
}

glm::vec3 normalAt(const Heightfield& terrain, float x, float z) {
    const float step = terrain.spacing();
    return glm::normalize(glm::vec3(-slopeAlong(terrain, x, z, step, 0), 1.0f, -slopeAlong(terrain, x, z, 0, step)));
}

float slopeDegreesAt(const Heightfield& terrain, float x, float z) {
    return glm::degrees(std::acos(std::clamp(normalAt(terrain, x, z).y, -1.0f, 1.0f)));
}

TerrainMesh makeTerrainMesh(const Heightfield& terrain) {
    const uint32_t n = terrain.resolution;
    TerrainMesh mesh;
    mesh.positions.reserve(size_t(n) * n);
    mesh.normals.reserve(size_t(n) * n);
    for (uint32_t iz = 0; iz < n; ++iz)
        for (uint32_t ix = 0; ix < n; ++ix) {
            const float x = terrain.coordinate(ix), z = terrain.coordinate(iz);
            mesh.positions.emplace_back(x, terrain.height(ix, iz), z);
            mesh.normals.push_back(normalAt(terrain, x, z));
        }
    mesh.indices.reserve(size_t(6) * (n - 1) * (n - 1));
    for (uint32_t iz = 0; iz + 1 < n; ++iz)
        for (uint32_t ix = 0; ix + 1 < n; ++ix) {
            const uint32_t corner = iz * n + ix; // +x is one vertex on, +z one row on
            // Seen from +y, +z points down the page, so (corner, +z, +x) turns counter-clockwise.
            mesh.indices.insert(mesh.indices.end(),
                                {corner, corner + n, corner + 1, corner + 1, corner + n, corner + n + 1});
        }
    return mesh;
}

} // namespace pf
