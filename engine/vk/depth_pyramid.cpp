#include "engine/vk/depth_pyramid.h"

#include "engine/vk/pipeline.h"
#include "shaders/shared/depth_pyramid_layouts.h"

#include "shaders/depth_reduce_comp.spv.h"
#include "shaders/depth_reduce_ms_comp.spv.h"

#include <algorithm>
#include <bit>

namespace pf {

namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// Read with texelFetch only: the sampler's filter never applies.
VkSampler createNearestSampler(GpuResources& owner) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = VK_LOD_CLAMP_NONE;
    return createSampler(owner, info);
}

DescriptorBinding pyramidRead(VkSampler sampler, VkImageView view) {
    DescriptorBinding b = sampledImage(DEPTH_PYRAMID_BINDING, kCompute, sampler, view);
    b.image.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    return b;
}

} // namespace

VkDescriptorSetLayout createDepthPyramidReadLayout(GpuResources& owner) {
    const DescriptorBinding table[] = {pyramidRead(VK_NULL_HANDLE, VK_NULL_HANDLE)};
    return createSetLayout(owner, table);
}

DepthPyramid createDepthPyramid(GpuResources& owner, const Image& depth) {
    DepthPyramid p;
    for (const PixelExtent& level : depthPyramidExtents({depth.extent.width, depth.extent.height}))
        p.extents.push_back({level.width, level.height});
    p.levels = uint32_t(p.extents.size());
    p.depth = depth.image;
    p.depthExtent = depth.extent;
    p.depthSamples = uint32_t(depth.samples);
    // Mips halve rounding down; a power-of-two level 0 makes every mip at
    // least as large as the level it holds, which halves rounding up.
    p.image = createImage(owner, {.extent = {std::bit_ceil(p.extents[0].width), std::bit_ceil(p.extents[0].height)},
                                  .format = VK_FORMAT_R32_SFLOAT,
                                  .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT, // tests read it back
                                  .mipLevels = p.levels});
    const VkSampler sampler = createNearestSampler(owner);

    std::vector<VkImageView> mips;
    for (uint32_t l = 0; l < p.levels; ++l) mips.push_back(createMipView(owner, p.image, l));
    std::vector<std::vector<DescriptorBinding>> tables;
    for (uint32_t l = 0; l < p.levels; ++l) {
        DescriptorBinding source =
            sampledImage(DEPTH_REDUCE_BINDING_SOURCE, kCompute, sampler, l ? mips[l - 1] : depth.view);
        if (l > 0) source.image.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        tables.push_back({source, storageImage(DEPTH_REDUCE_BINDING_TARGET, kCompute, mips[l])});
    }
    const VkDescriptorSetLayout levelLayout = createSetLayout(owner, tables[0]);
    const std::vector<DescriptorTable> views(tables.begin(), tables.end());
    p.levelSets = createSets(owner, levelLayout, views);
    p.layout = createPipelineLayout(owner, levelLayout, {kCompute, 0, sizeof(gpu::DepthReducePush)});
    p.otherLevels = createComputePipeline(owner, p.layout, spirv_depth_reduce_comp);
    p.firstLevel =
        p.depthSamples > 1 ? createComputePipeline(owner, p.layout, spirv_depth_reduce_ms_comp) : p.otherLevels;

    const DescriptorBinding read[] = {pyramidRead(sampler, p.image.view)};
    p.readSet = createSet(owner, createDepthPyramidReadLayout(owner), read);
    return p;
}

void recordDepthPyramid(VkCommandBuffer cmd, const DepthPyramid& p) {
    const VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    const VkImageSubresourceRange pyramidRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, p.levels, 0, 1};
    // The rendering's depth writes before the first level reads them; the
    // previous frame's late cull read the pyramid this overwrites
    // (write-after-read: execution only, its contents are not kept).
    const VkImageMemoryBarrier2 before[] = {
        imageMemoryBarrier(p.depth, depthRange,
                           {depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}),
        imageMemoryBarrier(p.image.image, pyramidRange,
                           {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL})};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = uint32_t(std::size(before));
    dependency.pImageMemoryBarriers = before;
    vkCmdPipelineBarrier2(cmd, &dependency);

    VkExtent2D source = p.depthExtent;
    for (uint32_t l = 0; l < p.levels; ++l) {
        const VkExtent2D target = p.extents[l];
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, l == 0 ? p.firstLevel : p.otherLevels);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0, 1, &p.levelSets[l], 0, nullptr);
        const gpu::DepthReducePush push{glm::uvec4(source.width, source.height, target.width, target.height),
                                        glm::uvec4(l == 0 ? p.depthSamples : 1u, 0u, 0u, 0u)};
        vkCmdPushConstants(cmd, p.layout, kCompute, 0, sizeof(push), &push);
        vkCmdDispatch(cmd, (target.width + DEPTH_REDUCE_GROUP_SIZE - 1) / DEPTH_REDUCE_GROUP_SIZE,
                      (target.height + DEPTH_REDUCE_GROUP_SIZE - 1) / DEPTH_REDUCE_GROUP_SIZE, 1);
        // The next level (or the late cull) reads this one.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        source = target;
    }
    // The rendering after the late cull loads and tests the depth buffer again.
    imageBarrier(cmd, p.depth, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0, depthStages,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
}

} // namespace pf
