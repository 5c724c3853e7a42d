// The FXAA pass (Lottes 2009, "FXAA" whitepaper; shaders/fxaa.frag): one
// full-screen triangle that reads a frame drawn with one sample a pixel and
// writes it with its edges smoothed into an image of the same size. A
// RenderTarget made for FXAA owns one and records it as its colour pass ends
// (target_pass.h).
#pragma once

#include "engine/vk/resources.h"

namespace pf {

// The pass reads and writes the sRGB images' bytes as they are, through
// views of this format: gamma-encoded, so its contrast tests see perceptual
// luma and no texel is decoded or encoded on the way.
constexpr VkFormat kFxaaViewFormat = VK_FORMAT_R8G8B8A8_UNORM;

struct FxaaPass {
    VkSampler sampler = VK_NULL_HANDLE; // of the combined image sampler; the shader only fetches texels
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;    // the source, through its kFxaaViewFormat view
    VkImageView outputView = VK_NULL_HANDLE; // the output in kFxaaViewFormat
    VkExtent2D extent{};                     // of the source and the output
};

// Owned by `owner`. `source` (SAMPLED usage) and `output` (COLOR_ATTACHMENT
// usage): one sample, the same size, 4 bytes a texel, made with
// VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT.
FxaaPass createFxaaPass(GpuResources& owner, const Image& source, const Image& output);

// Draws every pixel of the output, in COLOR_ATTACHMENT_OPTIMAL (its previous
// contents are not read), from the source, which must be in
// SHADER_READ_ONLY_OPTIMAL and visible to fragment shaders.
void recordFxaaPass(VkCommandBuffer cmd, const FxaaPass& pass);

} // namespace pf
