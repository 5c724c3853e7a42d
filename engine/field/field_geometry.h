// What the field's passes draw and cull from, uploaded once at load: the
// plant models' meshes and the billboards in one vertex and one index
// pool, the impostor atlas baked from them with its billboards' outlines,
// the terrain as drawn (decimated, in chunks), and the plants with their
// models (visible lists assigned) and the naive baseline's list.
#pragma once

#include "engine/field/impostor_atlas.h"
#include "engine/field/visible_lists.h"
#include "engine/scene/field_content.h"
#include "engine/scene/terrain_chunks.h"
#include "engine/vk/resources.h"

#include <array>
#include <vector>

namespace pf {

// The draw shaders read the field's buffers through texel views
// (field_common.glsl); the cull pass reads instances and models, the
// impostor bake the vertices, the canopy bake the nodes, as storage buffers.
constexpr VkBufferUsageFlags kStorageAndTexels =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

// A device-local buffer holding `data`, owned by `owner` (kSmallestBufferBytes
// of zeros when it is empty: the instances of a field with no plant).
template <class T>
Buffer uploadFieldVector(GpuResources& owner, const std::vector<T>& data, VkBufferUsageFlags usage) {
    return createDeviceBufferWithData(owner, data.data(), data.size() * sizeof(T), usage);
}

struct FieldGeometry {
    Buffer vertices, indices;               // FieldVertex and index pools: every model's meshes, then the billboards
    std::array<MeshRange, 3> billboards{};  // 1, 2, 3 quads
    ImpostorAtlas atlas;                    // baked from the pools at the scene's sun elevation
    Buffer outlines;                        // atlas.outlines: the rectangle each layer's billboards are drawn as
    Heightfield drawnTerrain;               // the terrain as its mesh draws it
    TerrainChunks terrainChunks;            // its chunks, in terrainIndices
    Buffer terrainVertices, terrainIndices; // TerrainVertex[] (texels), the chunks' indices
};

// Appends the billboards to `content.models` and bakes the atlas into it
// (each model's gpu.impostor and impostorQuad). Owned by `owner`.
FieldGeometry createFieldGeometry(GpuResources& owner, FieldContent& content, const ImpostorSettings& impostors);

struct FieldPlantBuffers {
    Buffer models;       // gpu::PlantModel[] with visible lists, storage and texels
    Buffer instances;    // gpu::FieldInstance[], storage and texels
    Buffer naiveVisible; // naiveVisibleList: the naive baseline's draws read it
};

FieldPlantBuffers uploadFieldPlants(GpuResources& owner, const FieldPlants& plants);

} // namespace pf
