#include "engine/window/window_blit.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/render_target.h"
#include "engine/vk/target_pass.h"
#include "shaders/shared/window_blit_layouts.h"

#include "shaders/fullscreen_vert.spv.h"
#include "shaders/window_blit_frag.spv.h"

namespace pf {

VkFormat windowBlitSourceFormat(VkFormat outputFormat) {
    switch (outputFormat) {
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32: return kColorFormat;
    default: return VK_FORMAT_R8G8B8A8_UNORM;
    }
}

WindowBlit createWindowBlit(GpuResources& owner, const Image& source, VkFormat outputFormat) {
    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = sampler.minFilter = VK_FILTER_LINEAR;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    const DescriptorBinding table[] = {
        sampledImage(WINDOW_BLIT_BINDING_SOURCE, VK_SHADER_STAGE_FRAGMENT_BIT, createSampler(owner, sampler),
                     createImageView(owner, source, windowBlitSourceFormat(outputFormat)))};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    WindowBlit blit;
    blit.set = createSet(owner, setLayout, table);
    blit.pipelineLayout = createPipelineLayout(owner, setLayout);
    blit.pipeline = createColorOnlyPipeline(owner, spirv_fullscreen_vert, spirv_window_blit_frag, blit.pipelineLayout,
                                            outputFormat);
    return blit;
}

void recordWindowBlit(VkCommandBuffer cmd, const WindowBlit& blit, VkImageView output, VkExtent2D extent) {
    beginColorOnlyRendering(cmd, output, VK_ATTACHMENT_LOAD_OP_DONT_CARE, extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, blit.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, blit.pipelineLayout, 0, 1, &blit.set, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

} // namespace pf
