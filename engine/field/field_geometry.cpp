#include "engine/field/field_geometry.h"

#include "engine/scene/camera.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// The drawn terrain keeps at most this many samples a side: far cells of a
// finer grid are a pixel or two wide, and a CPU rasteriser pays per triangle.
constexpr uint32_t kTerrainDrawSamples = 129;
// Cells a side of the chunks a frame draws or leaves out (terrain_chunks.h):
// 64 chunks of 512 triangles for the most drawn samples.
constexpr uint32_t kTerrainChunkCells = 16;

// Every k-th sample (k the smallest step that fits), edges kept; a grid the
// step does not divide (a terrain grown to a plant count) is resampled
// bilinearly at maxSamples a side instead.
Heightfield decimated(const Heightfield& terrain, uint32_t maxSamples) {
    const uint32_t step = (terrain.resolution - 1 + maxSamples - 2) / (maxSamples - 1);
    if (step <= 1) return terrain;
    const bool whole = (terrain.resolution - 1) % step == 0;
    Heightfield coarse;
    coarse.resolution = whole ? (terrain.resolution - 1) / step + 1 : maxSamples;
    coarse.size = terrain.size;
    coarse.heights.reserve(size_t(coarse.resolution) * coarse.resolution);
    for (uint32_t z = 0; z < coarse.resolution; ++z)
        for (uint32_t x = 0; x < coarse.resolution; ++x)
            coarse.heights.push_back(whole ? terrain.height(x * step, z * step)
                                           : heightAt(terrain, coarse.coordinate(x), coarse.coordinate(z)));
    return coarse;
}

} // namespace

FieldGeometry createFieldGeometry(GpuResources& owner, FieldContent& content, const ImpostorSettings& impostors) {
    FieldGeometry g;
    PlantModelPool& pool = content.models;
    for (uint32_t quads = 1; quads <= 3; ++quads) g.billboards[quads - 1] = appendBillboardMesh(pool, quads);
    g.vertices = uploadFieldVector(owner, pool.vertices, kStorageAndTexels);
    g.indices = uploadFieldVector(owner, pool.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    // The shadow frames are seen from the scene's sun, fixed per scene.
    const float sunElevation = std::asin(std::clamp(sunDirection(environmentOf(content.scene)).y, -1.0f, 1.0f));
    g.atlas = bakeImpostorAtlas(owner, pool, g.vertices, g.indices, sunElevation, impostors);
    g.outlines = uploadFieldVector(owner, g.atlas.outlines, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);

    g.drawnTerrain = decimated(content.terrain, kTerrainDrawSamples);
    const TerrainMesh mesh = makeTerrainMesh(g.drawnTerrain);
    std::vector<gpu::TerrainVertex> terrain(mesh.positions.size());
    for (size_t i = 0; i < terrain.size(); ++i)
        terrain[i] = {glm::vec4(mesh.positions[i], 0.0f), glm::vec4(mesh.normals[i], 0.0f)};
    g.terrainVertices = uploadFieldVector(owner, terrain, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    g.terrainChunks = makeTerrainChunks(mesh, g.drawnTerrain.resolution, kTerrainChunkCells);
    g.terrainIndices = uploadFieldVector(owner, g.terrainChunks.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    return g;
}

FieldPlantBuffers uploadFieldPlants(GpuResources& owner, const FieldPlants& plants) {
    FieldPlantBuffers b;
    b.models = uploadFieldVector(owner, plants.models, kStorageAndTexels);
    b.instances = uploadFieldVector(owner, plants.instances, kStorageAndTexels);
    b.naiveVisible = uploadFieldVector(owner, naiveVisibleList(uint32_t(plants.instances.size())),
                                       VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    return b;
}

} // namespace pf
