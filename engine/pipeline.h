// Shader modules and graphics pipelines for dynamic rendering.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>

namespace pf {

VkShaderModule createShaderModule(VkDevice device, const uint32_t* code, size_t bytes);

template <size_t N>
VkShaderModule createShaderModule(VkDevice device, const uint32_t (&code)[N]) {
    return createShaderModule(device, code, sizeof(code));
}

struct GraphicsPipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE;
    VkShaderModule fragment = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkFormat colorFormat = VK_FORMAT_UNDEFINED;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
    bool depthTest = true;
    bool depthWrite = true;
    // Depth-only passes (shadow maps) leave colorFormat UNDEFINED: no colour
    // attachment. Their slope-scaled bias keeps lit surfaces from shadowing
    // themselves.
    float depthBiasConstant = 0.0f;
    float depthBiasSlope = 0.0f;
    // Colour passes use a negative-height viewport (y up, counter-clockwise
    // front faces); passes with an ordinary viewport say false.
    bool flippedViewport = true;
};

// A compute pipeline of `module`'s main; destroys the module.
VkPipeline createComputePipeline(VkDevice device, VkPipelineLayout layout, VkShaderModule module);

// Vertices are pulled from storage buffers, so there is no vertex input;
// viewport and scissor are dynamic.
VkPipeline createGraphicsPipeline(VkDevice device, const GraphicsPipelineDesc& desc);

} // namespace pf
