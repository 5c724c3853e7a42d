#include "engine/vk/fxaa_pass.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "shaders/shared/fxaa_layouts.h"

#include "shaders/fullscreen_vert.spv.h"
#include "shaders/fxaa_frag.spv.h"

namespace pf {

FxaaPass createFxaaPass(GpuResources& owner, const Image& source, const Image& output) {
    FxaaPass pass;
    pass.extent = source.extent;
    pass.outputView = createImageView(owner, output, kFxaaViewFormat);
    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    pass.sampler = createSampler(owner, sampler);

    const DescriptorBinding table[] = {sampledImage(FXAA_BINDING_SOURCE, VK_SHADER_STAGE_FRAGMENT_BIT, pass.sampler,
                                                    createImageView(owner, source, kFxaaViewFormat))};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    pass.set = createSet(owner, setLayout, table);
    pass.pipelineLayout = createPipelineLayout(owner, setLayout);

    pass.pipeline =
        createColorOnlyPipeline(owner, spirv_fullscreen_vert, spirv_fxaa_frag, pass.pipelineLayout, kFxaaViewFormat);
    return pass;
}

void recordFxaaPass(VkCommandBuffer cmd, const FxaaPass& pass) {
    // The triangle covers every pixel, so nothing is loaded. An ordinary
    // viewport: gl_FragCoord is the pixel of the source to read.
    beginColorOnlyRendering(cmd, pass.outputView, VK_ATTACHMENT_LOAD_OP_DONT_CARE, pass.extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 1, &pass.set, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

} // namespace pf
