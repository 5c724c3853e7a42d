#include "engine/compute_set.h"

#include "engine/vk_check.h"

#include <vector>

namespace pf {

ComputeSet createComputeSet(const GpuContext& ctx, std::span<const VkBuffer> buffers) {
    const uint32_t count = uint32_t(buffers.size());
    std::vector<VkDescriptorSetLayoutBinding> bindings(count);
    for (uint32_t b = 0; b < count; ++b)
        bindings[b] = {b, b == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                       VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    ComputeSet set;
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = count;
    layoutInfo.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &layoutInfo, nullptr, &set.setLayout));

    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &set.setLayout;
    VK_CHECK(vkCreatePipelineLayout(ctx.device, &pipelineLayoutInfo, nullptr, &set.pipelineLayout));

    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, count - 1}};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 2;
    poolInfo.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &poolInfo, nullptr, &set.descriptorPool));
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = set.descriptorPool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &set.setLayout;
    VK_CHECK(vkAllocateDescriptorSets(ctx.device, &allocInfo, &set.descriptorSet));

    std::vector<VkDescriptorBufferInfo> infos(count);
    std::vector<VkWriteDescriptorSet> writes(count);
    for (uint32_t b = 0; b < count; ++b) {
        infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
        writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = set.descriptorSet;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = bindings[b].descriptorType;
        writes[b].pBufferInfo = &infos[b];
    }
    vkUpdateDescriptorSets(ctx.device, count, writes.data(), 0, nullptr);
    return set;
}

void destroyComputeSet(const GpuContext& ctx, ComputeSet& set) {
    vkDestroyPipelineLayout(ctx.device, set.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(ctx.device, set.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(ctx.device, set.setLayout, nullptr);
    set = {};
}

void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set.pipelineLayout, 0, 1, &set.descriptorSet, 0,
                            nullptr);
}

} // namespace pf
