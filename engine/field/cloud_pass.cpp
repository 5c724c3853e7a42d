#include "engine/field/cloud_pass.h"

#include "engine/scene/cloud_billboards.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/render_target.h"

#include "shaders/cloud_frag.spv.h"
#include "shaders/cloud_vert.spv.h"

#include <cstring>

namespace pf {

CloudPass createCloudPass(GpuResources& owner, const std::vector<Cloud>& clouds, const Buffer& frameUniforms,
                          VkSampleCountFlagBits samples) {
    CloudPass pass;
    for (const Cloud& cloud : clouds) pass.spheres += uint32_t(cloud.spheres.size());
    if (pass.spheres == 0) return pass;
    pass.billboards = createHostBuffer(owner, VkDeviceSize(pass.spheres) * sizeof(gpu::CloudBillboard),
                                       VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const DescriptorBinding table[] = {
        uniformBuffer(CLOUD_BINDING_FRAME, kStages, frameUniforms),
        texelBuffer(CLOUD_BINDING_SPHERES, VK_SHADER_STAGE_VERTEX_BIT,
                    createTexelView(owner, pass.billboards, VK_FORMAT_R32G32B32A32_UINT))};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    pass.set = createSet(owner, setLayout, table);
    pass.layout = createPipelineLayout(owner, setLayout);

    GpuResources modules(owner.ctx());
    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(modules, spirv_cloud_vert);
    desc.fragment = createShaderModule(modules, spirv_cloud_frag);
    desc.layout = pass.layout;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = samples;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthWrite = false; // seen through: what lies behind a sphere is already drawn
    desc.blend = GraphicsPipelineDesc::Blend::premultipliedAlpha;
    pass.pipeline = createGraphicsPipeline(owner, desc);
    return pass;
}

void setCloudView(const CloudPass& pass, const Scene& scene, float time, const glm::vec3& camera,
                  const glm::vec3& forward) {
    if (pass.spheres == 0) return;
    const std::vector<gpu::CloudBillboard> billboards =
        cloudBillboards(scene.clouds, scene.wind, time, camera, forward);
    std::memcpy(pass.billboards.mapped, billboards.data(), billboards.size() * sizeof(gpu::CloudBillboard));
}

void recordCloudPass(VkCommandBuffer cmd, const CloudPass& pass) {
    if (pass.spheres == 0) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.layout, 0, 1, &pass.set, 0, nullptr);
    vkCmdDraw(cmd, CLOUD_BILLBOARD_VERTICES, pass.spheres, 0, 0);
}

} // namespace pf
