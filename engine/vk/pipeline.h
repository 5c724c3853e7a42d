// Shader modules and graphics pipelines for dynamic rendering.
#pragma once

#include "engine/vk/gpu_resources.h"

#include <cstdint>
#include <span>

namespace pf {

// Modules are needed only while pipelines are made: callers give them a
// scratch owner that outlives those calls.
VkShaderModule createShaderModule(GpuResources& owner, std::span<const uint32_t> spirv);

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
    // Meshes are counter-clockwise seen from outside. Colour passes flip y
    // with a negative-height viewport, which keeps that winding; an ordinary
    // viewport with a y-up projection mirrors it (clockwise).
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    // A second colour attachment (the impostor bake's normal + depth).
    VkFormat secondColorFormat = VK_FORMAT_UNDEFINED;
    // Cull mode set per draw with vkCmdSetCullMode; cullMode is then ignored.
    bool dynamicCullMode = false;
    // How the first colour attachment is blended: replaced (opaque passes),
    // as premultiplied alpha (colour + destination · (1 − alpha):
    // transparent passes, the clouds) or multiplied (destination · colour:
    // the clouds' shadows darkening the ground).
    enum class Blend { none, premultipliedAlpha, multiply } blend = Blend::none;
};

// Pipelines are owned by `owner`.
// A compute pipeline of the shader's main.
// `specialization`, when given, sets the shader's specialization constants.
VkPipeline createComputePipeline(GpuResources& owner, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                                 const VkSpecializationInfo* specialization = nullptr);

// Vertices are pulled from storage buffers, so there is no vertex input;
// viewport and scissor are dynamic.
VkPipeline createGraphicsPipeline(GpuResources& owner, const GraphicsPipelineDesc& desc);
// A pipeline of the full-frame passes over one colour attachment (FXAA, the
// text overlay): no depth, no face culling; its shader modules live only
// while it is made.
VkPipeline createColorOnlyPipeline(GpuResources& owner, std::span<const uint32_t> vertexSpirv,
                                   std::span<const uint32_t> fragmentSpirv, VkPipelineLayout layout,
                                   VkFormat colorFormat);

} // namespace pf
