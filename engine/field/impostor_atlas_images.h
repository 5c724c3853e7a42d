// The impostor atlas's images (impostor_atlas.h): how many layers every
// model's rings of frames take, checked against the device; the colour,
// normal + depth and shadow-frame images with their full mip chains and the
// billboards' sampler; each model's first layers; the mip chains blitted
// once the bake has drawn level 0; and the outlines read back from the
// coverage. The bake itself (impostor_bake.cpp) draws the frames into them.
#pragma once

#include "engine/field/impostor_atlas.h"
#include "engine/vk/resources.h"

#include <initializer_list>
#include <vector>

namespace pf {

inline constexpr VkFormat kAtlasColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
inline constexpr VkFormat kAtlasNormalFormat = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr VkFormat kShadowFrameFormat = VK_FORMAT_R8G8_UNORM;

// How many models' rings of frames the device's image array layers hold
// (impostorSources shares frames past it); throws on settings the device
// cannot make images of.
uint32_t impostorModelCapacity(const GpuContext& ctx, const ImpostorSettings& settings);

// The colour images' layer count: the rings of frames of every model that
// shows its own (impostor_sources.h).
uint32_t atlasLayers(const std::vector<uint32_t>& sources, const ImpostorSettings& settings);

// The three images with their full mip chains (the shadow frames one ring
// per model), and the billboards' sampler.
ImpostorAtlas createAtlas(GpuResources& owner, const ImpostorSettings& settings, uint32_t layers);

// Each model's first colour and shadow layers, frames, quads per billboard
// and baked box: those of the model whose frames it shows (`sources`).
void assignImpostorLayers(PlantModelPool& pool, const ImpostorSettings& settings, const std::vector<uint32_t>& sources);

// A barrier over mips [baseMip, baseMip + mips) of an atlas image's first
// `layers` layers, and a dependency recording the image barriers given.
VkImageMemoryBarrier2 atlasBarrier(const Image& image, uint32_t baseMip, uint32_t mips, uint32_t layers,
                                   const ImageTransition& t);
void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& images);

// A linear blit halving a square of `side` texels (none below 1) from the
// `from` layers into the `to` layers: every destination texel is sampled at
// the corner its 2×2 source texels share, with weight 1/4 each, a box filter
// of the premultiplied values and the coverage. The frames' 2:1 filtering
// and the mip chains both use it.
VkImageBlit halvingBlit(uint32_t side, const VkImageSubresourceLayers& from, const VkImageSubresourceLayers& to);

// Mips of `images` (size² at level 0, `mips` levels, `layers` layers): level
// k is blitted from level k-1 (premultiplied values and coverage average
// correctly); then every level is left for the billboards' fragment shaders.
void recordMipChain(VkCommandBuffer cmd, std::initializer_list<const Image*> images, uint32_t size, uint32_t mips,
                    uint32_t layers);

// Reads the coverage of every layer back at mip kOutlineMip (or the last)
// and makes each layer's outline. The atlas is sampled before and after.
std::vector<ImpostorOutline> readOutlines(const GpuContext& ctx, const ImpostorAtlas& atlas);

} // namespace pf
