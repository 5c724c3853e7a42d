// The depth pyramid of a render target (docs/CULLING.md, "The depth
// pyramid"): after the colour pass's first part, a compute pass reduces its
// depth buffer level by level into a mip chain of R32_SFLOAT where each texel
// holds the largest (farthest) depth of the pixels under it. Level 0 is half
// the depth buffer, each level half the one below, rounding up, down to 1×1;
// a level of odd size clamps its reads at the last row and column, so every
// texel covers exactly pixels (x, y)·2^(l+1) to (x + 1, y + 1)·2^(l+1) − 1
// and no pixel is left out (a power-of-two pyramid over a viewport of
// another size would drop or stretch some). The reduction is done in the
// shader rather than by a sampler reduction mode (VK_EXT_sampler_filter_minmax,
// which zeux/niagara uses where it can) so a multisampled depth buffer is
// reduced over all its samples, not one of them, and no device feature is
// needed. Its sizes and the CPU reference of the reduction are
// engine/image/depth_pyramid_levels.h.
#pragma once

#include "engine/image/depth_pyramid_levels.h"
#include "engine/vk/descriptors.h"

#include <vector>

namespace pf {

struct DepthPyramid {
    Image image; // R32_SFLOAT, `levels` mips (level 0 a power of two a side); image.view sees them all
    uint32_t levels = 0;
    std::vector<VkExtent2D> extents; // per level, the texels it holds (the top left of its mip)
    VkImage depth = VK_NULL_HANDLE;  // the depth buffer it is built from
    VkExtent2D depthExtent{};
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline firstLevel = VK_NULL_HANDLE; // depth_reduce_ms.comp for a multisampled depth buffer
    VkPipeline otherLevels = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> levelSets; // level l: the depth buffer (l = 0) or level l − 1 → level l
    uint32_t depthSamples = 1;
    VkDescriptorSet readSet = VK_NULL_HANDLE; // DEPTH_PYRAMID_BINDING: every level, for the late cull
};

// The pyramid of `depth` (a D32_SFLOAT image made with SAMPLED usage, one
// sample or several), its pipelines and sets, owned by `owner`.
DepthPyramid createDepthPyramid(GpuResources& owner, const Image& depth);

// The layout of the set the pyramid is read through (a combined image
// sampler of every level at DEPTH_PYRAMID_BINDING, compute stage, in
// GENERAL). Every call makes an identically defined layout, so a pipeline
// layout made with one is compatible with the readSet of any pyramid.
VkDescriptorSetLayout createDepthPyramidReadLayout(GpuResources& owner);

// Records the reduction after a rendering that stored the depth buffer: the
// depth buffer goes from DEPTH_ATTACHMENT_OPTIMAL to shader reads and back
// (for a rendering that loads it), the pyramid is left in GENERAL, readable
// by compute shaders.
void recordDepthPyramid(VkCommandBuffer cmd, const DepthPyramid& pyramid);

} // namespace pf
