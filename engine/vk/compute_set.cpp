#include "engine/vk/compute_set.h"

#include "engine/vk/vk_check.h"

#include <vector>

namespace pf {

ComputeSet createComputeSet(GpuResources& owner, std::span<const ComputeBinding> bindings) {
    VkDevice device = owner.ctx().device;
    const uint32_t count = uint32_t(bindings.size());
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings(count);
    for (uint32_t b = 0; b < count; ++b)
        layoutBindings[b] = {b, bindings[b].type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    ComputeSet set;
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = count;
    layoutInfo.pBindings = layoutBindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device, &layoutInfo, nullptr, &set.setLayout));
    owner.own(set.setLayout);

    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &set.setLayout;
    VK_CHECK(vkCreatePipelineLayout(device, &pipelineLayoutInfo, nullptr, &set.pipelineLayout));
    owner.own(set.pipelineLayout);

    set.descriptorPool = createDescriptorPool(owner, layoutBindings, 1);
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = set.descriptorPool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &set.setLayout;
    VK_CHECK(vkAllocateDescriptorSets(device, &allocInfo, &set.descriptorSet));

    std::vector<VkDescriptorBufferInfo> infos(count);
    std::vector<VkWriteDescriptorSet> writes(count);
    for (uint32_t b = 0; b < count; ++b) {
        writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = set.descriptorSet;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = bindings[b].type;
        if (bindings[b].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) {
            writes[b].pTexelBufferView = &bindings[b].view;
        } else {
            infos[b] = {bindings[b].buffer, 0, VK_WHOLE_SIZE};
            writes[b].pBufferInfo = &infos[b];
        }
    }
    vkUpdateDescriptorSets(device, count, writes.data(), 0, nullptr);
    return set;
}

ComputeSet createComputeSet(GpuResources& owner, std::span<const VkBuffer> buffers) {
    std::vector<ComputeBinding> bindings(buffers.size());
    for (size_t b = 0; b < buffers.size(); ++b)
        bindings[b] = {b == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[b]};
    return createComputeSet(owner, bindings);
}

void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set.pipelineLayout, 0, 1, &set.descriptorSet, 0,
                            nullptr);
}

} // namespace pf
