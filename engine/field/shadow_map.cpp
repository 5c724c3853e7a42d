#include "engine/field/shadow_map.h"

#include "engine/vk/target_pass.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace pf {

ShadowMap createShadowMap(GpuResources& owner, uint32_t size) {
    ShadowMap map;
    map.size = size;
    map.depth = createImage(owner, {.extent = {size, size},
                                    .format = kShadowFormat,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                             VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    .aspect = VK_IMAGE_ASPECT_DEPTH_BIT});
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE; // outside the map: lit
    info.compareEnable = VK_TRUE;
    info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    info.maxLod = 0.0f;
    map.sampler = createSampler(owner, info);

    // Sampled before the first shadow pass (e.g. a frame with shadows off):
    // start in the layout the shaders read, cleared to "lit".
    submitAndWait(owner.ctx(), [&](VkCommandBuffer cmd) {
        imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                     {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL});
        const VkClearDepthStencilValue far{1.0f, 0};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        vkCmdClearDepthStencilImage(cmd, map.depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &range);
        imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                     {VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    });
    return map;
}

glm::mat4 sunViewProjection(const glm::vec3& sunDirection, const glm::vec3& focus, float radius, float depthRadius,
                            uint32_t mapSize) {
    const glm::vec3 up = std::abs(sunDirection.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAtRH(glm::vec3(0.0f), -sunDirection, up);
    // Snap the focus, seen from the sun, to the texel grid.
    const float texel = 2.0f * radius / float(mapSize);
    glm::vec3 centre = glm::vec3(view * glm::vec4(focus, 1.0f));
    centre.x = std::floor(centre.x / texel) * texel;
    centre.y = std::floor(centre.y / texel) * texel;
    // View space looks down -z: near and far are distances along it.
    const glm::mat4 proj = glm::orthoRH_ZO(centre.x - radius, centre.x + radius, centre.y - radius, centre.y + radius,
                                           -centre.z - depthRadius, -centre.z + depthRadius);
    return proj * view;
}

void beginShadowPass(VkCommandBuffer cmd, const ShadowMap& map) {
    // The previous frame's fragment shaders read the map; this pass overwrites it.
    const VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, depthStages,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});

    const VkRenderingAttachmentInfo depth = clearedDepthAttachment(map.depth.view, VK_ATTACHMENT_STORE_OP_STORE);
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {map.size, map.size}};
    rendering.layerCount = 1;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);

    const VkViewport viewport{0.0f, 0.0f, float(map.size), float(map.size), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {map.size, map.size}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void endShadowPass(VkCommandBuffer cmd, const ShadowMap& map) {
    vkCmdEndRendering(cmd);
    // The colour pass samples the depth this pass wrote.
    imageBarrier(cmd, map.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
}

} // namespace pf
