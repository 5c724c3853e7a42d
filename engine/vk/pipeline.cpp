#include "engine/vk/pipeline.h"

#include "engine/vk/vk_check.h"

namespace pf {

VkShaderModule createShaderModule(GpuResources& owner, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule(owner.ctx().device, &info, nullptr, &module));
    return owner.own(module);
}

VkPipeline createGraphicsPipeline(GpuResources& owner, const GraphicsPipelineDesc& desc) {
    VkPipelineShaderStageCreateInfo stages[2]{};
    stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = desc.vertex;
    stages[0].pName = "main";
    stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = desc.fragment;
    stages[1].pName = "main";

    VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cullMode;
    raster.frontFace = desc.frontFace;
    raster.lineWidth = 1.0f;
    raster.depthBiasEnable = desc.depthBiasConstant != 0.0f || desc.depthBiasSlope != 0.0f;
    raster.depthBiasConstantFactor = desc.depthBiasConstant;
    raster.depthBiasSlopeFactor = desc.depthBiasSlope;

    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = desc.samples;

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depthTest;
    depth.depthWriteEnable = desc.depthWrite;
    depth.depthCompareOp = desc.depthCompare;

    const VkFormat colorFormats[2] = {desc.colorFormat, desc.secondColorFormat};
    const uint32_t colorCount = desc.colorFormat == VK_FORMAT_UNDEFINED         ? 0
                                : desc.secondColorFormat == VK_FORMAT_UNDEFINED ? 1
                                                                                : 2;
    VkPipelineColorBlendAttachmentState blendAttachments[2]{};
    for (VkPipelineColorBlendAttachmentState& b : blendAttachments)
        b.colorWriteMask =
            VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (desc.blend != GraphicsPipelineDesc::Blend::none) {
        VkPipelineColorBlendAttachmentState& b = blendAttachments[0];
        b.blendEnable = VK_TRUE;
        const bool multiply = desc.blend == GraphicsPipelineDesc::Blend::multiply;
        b.srcColorBlendFactor = b.srcAlphaBlendFactor = multiply ? VK_BLEND_FACTOR_ZERO : VK_BLEND_FACTOR_ONE;
        b.dstColorBlendFactor = b.dstAlphaBlendFactor =
            multiply ? VK_BLEND_FACTOR_SRC_COLOR : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = colorCount;
    blend.pAttachments = blendAttachments;

    VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR, VK_DYNAMIC_STATE_CULL_MODE};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = desc.dynamicCullMode ? 3 : 2;
    dynamic.pDynamicStates = dynamicStates;

    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = colorCount;
    rendering.pColorAttachmentFormats = colorFormats;
    rendering.depthAttachmentFormat = desc.depthFormat;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = desc.layout;

    VkPipeline pipeline;
    VK_CHECK(vkCreateGraphicsPipelines(owner.ctx().device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return owner.own(pipeline);
}

VkPipeline createColorOnlyPipeline(GpuResources& owner, std::span<const uint32_t> vertexSpirv,
                                   std::span<const uint32_t> fragmentSpirv, VkPipelineLayout layout,
                                   VkFormat colorFormat) {
    GpuResources modules(owner.ctx());
    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(modules, vertexSpirv);
    desc.fragment = createShaderModule(modules, fragmentSpirv);
    desc.layout = layout;
    desc.colorFormat = colorFormat;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = desc.depthWrite = false;
    return createGraphicsPipeline(owner, desc);
}

VkPipeline createComputePipeline(GpuResources& owner, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                                 const VkSpecializationInfo* specialization) {
    GpuResources scratch(owner.ctx());
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = createShaderModule(scratch, spirv);
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = specialization;
    info.layout = layout;
    VkPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(owner.ctx().device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return owner.own(pipeline);
}

} // namespace pf
