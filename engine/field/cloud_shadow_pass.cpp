#include "engine/field/cloud_shadow_pass.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/render_target.h"
#include "shaders/shared/cloud_layouts.h"

#include "shaders/cloud_shadow_frag.spv.h"
#include "shaders/cloud_shadow_vert.spv.h"

namespace pf {

CloudShadowPass createCloudShadowPass(GpuResources& owner, const std::vector<Cloud>& clouds, const glm::vec3& sun,
                                      const Buffer& frameUniforms, const Buffer& terrainVertices,
                                      VkSampleCountFlagBits samples) {
    CloudShadowPass pass;
    pass.map = bakeCloudShadows(clouds, sun);
    if (pass.map.width == 0) return pass;
    pass.transmittance =
        createDeviceBufferWithData(owner, pass.map.transmittance.data(), pass.map.transmittance.size() * sizeof(float),
                                   VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const DescriptorBinding table[] = {
        uniformBuffer(CLOUD_SHADOW_BINDING_FRAME, kStages, frameUniforms),
        texelBuffer(CLOUD_SHADOW_BINDING_TERRAIN, VK_SHADER_STAGE_VERTEX_BIT,
                    createTexelView(owner, terrainVertices, VK_FORMAT_R32G32B32A32_UINT)),
        texelBuffer(CLOUD_SHADOW_BINDING_MAP, VK_SHADER_STAGE_FRAGMENT_BIT,
                    createTexelView(owner, pass.transmittance, VK_FORMAT_R32_UINT))};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    pass.set = createSet(owner, setLayout, table);
    pass.layout =
        createPipelineLayout(owner, setLayout, {VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(gpu::CloudShadowPush)});

    GpuResources modules(owner.ctx());
    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(modules, spirv_cloud_shadow_vert);
    desc.fragment = createShaderModule(modules, spirv_cloud_shadow_frag);
    desc.layout = pass.layout;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = samples;
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.depthWrite = false;
    // The terrain's own depth, from another shader, may differ in its last
    // bits: pulled towards the camera it passes, while a plant in front,
    // metres nearer, still hides the ground behind it.
    desc.depthBiasConstant = -8.0f;
    desc.depthBiasSlope = -1.0f;
    desc.blend = GraphicsPipelineDesc::Blend::multiply;
    pass.pipeline = createGraphicsPipeline(owner, desc);
    return pass;
}

void recordCloudShadowPass(VkCommandBuffer cmd, const CloudShadowPass& pass, const Buffer& terrainIndices,
                           const TerrainRanges& ranges, const glm::vec3& drift) {
    if (pass.map.width == 0) return;
    const gpu::CloudShadowPush push{glm::vec4(drift.x, 0.0f, drift.z, float(pass.map.height)),
                                    glm::vec4(pass.map.origin, 1.0f / pass.map.texel, float(pass.map.width))};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.layout, 0, 1, &pass.set, 0, nullptr);
    vkCmdPushConstants(cmd, pass.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
    vkCmdBindIndexBuffer(cmd, terrainIndices.buffer, 0, VK_INDEX_TYPE_UINT32);
    for (const std::vector<IndexRange>* list : {&ranges.shadowed, &ranges.sunlit})
        for (const IndexRange& range : *list) vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
}

} // namespace pf
