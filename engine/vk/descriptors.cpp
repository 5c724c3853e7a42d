#include "engine/vk/descriptors.h"

#include "engine/vk/vk_check.h"

namespace pf {

DescriptorBinding uniformBuffer(uint32_t binding, VkShaderStageFlags stages, const Buffer& buffer) {
    return {binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages, buffer.buffer};
}

DescriptorBinding storageBuffer(uint32_t binding, VkShaderStageFlags stages, const Buffer& buffer) {
    return {binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, stages, buffer.buffer};
}

DescriptorBinding texelBuffer(uint32_t binding, VkShaderStageFlags stages, VkBufferView view) {
    return {binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages, VK_NULL_HANDLE, view};
}

DescriptorBinding sampledImage(uint32_t binding, VkShaderStageFlags stages, VkSampler sampler, VkImageView view) {
    return {binding,        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
            stages,         VK_NULL_HANDLE,
            VK_NULL_HANDLE, {sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
}

DescriptorBinding storageImage(uint32_t binding, VkShaderStageFlags stages, VkImageView view) {
    return {binding,        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
            stages,         VK_NULL_HANDLE,
            VK_NULL_HANDLE, {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL}};
}

VkDescriptorSetLayout createSetLayout(GpuResources& owner, DescriptorTable table) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const DescriptorBinding& b : table) bindings.push_back({b.binding, b.type, 1, b.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(owner.ctx().device, &info, nullptr, &layout));
    return owner.own(layout);
}

VkDescriptorPool createDescriptorPool(GpuResources& owner, DescriptorTable table, uint32_t sets) {
    // One pool size per binding: the pool sums them by type.
    std::vector<VkDescriptorPoolSize> sizes;
    for (const DescriptorBinding& b : table) sizes.push_back({b.type, sets});
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = sets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(owner.ctx().device, &info, nullptr, &pool));
    return owner.own(pool);
}

std::vector<VkDescriptorSet> createSets(GpuResources& owner, VkDescriptorSetLayout layout,
                                        std::span<const DescriptorTable> tables) {
    const uint32_t count = uint32_t(tables.size());
    const std::vector<VkDescriptorSetLayout> layouts(count, layout);
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = createDescriptorPool(owner, tables.front(), count);
    info.descriptorSetCount = count;
    info.pSetLayouts = layouts.data();
    std::vector<VkDescriptorSet> sets(count);
    VK_CHECK(vkAllocateDescriptorSets(owner.ctx().device, &info, sets.data()));
    for (uint32_t i = 0; i < count; ++i) writeSet(owner.ctx().device, sets[i], tables[i]);
    return sets;
}

VkDescriptorSet createSet(GpuResources& owner, VkDescriptorSetLayout layout, DescriptorTable table) {
    return createSets(owner, layout, {&table, 1}).front();
}

VkPipelineLayout createPipelineLayout(GpuResources& owner, VkDescriptorSetLayout setLayout, VkPushConstantRange push) {
    return createPipelineLayout(owner, std::span<const VkDescriptorSetLayout>(&setLayout, 1), push);
}

VkPipelineLayout createPipelineLayout(GpuResources& owner, std::span<const VkDescriptorSetLayout> setLayouts,
                                      VkPushConstantRange push) {
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(setLayouts.size());
    info.pSetLayouts = setLayouts.data();
    info.pushConstantRangeCount = push.size > 0 ? 1 : 0;
    info.pPushConstantRanges = &push;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(owner.ctx().device, &info, nullptr, &layout));
    return owner.own(layout);
}

void writeSet(VkDevice device, VkDescriptorSet set, DescriptorTable table) {
    // Sized up front: the writes point into it.
    std::vector<VkDescriptorBufferInfo> buffers(table.size());
    std::vector<VkWriteDescriptorSet> writes(table.size());
    for (size_t i = 0; i < table.size(); ++i) {
        const DescriptorBinding& b = table[i];
        VkWriteDescriptorSet& w = writes[i];
        w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = b.binding;
        w.descriptorCount = 1;
        w.descriptorType = b.type;
        switch (b.type) {
        case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER: w.pTexelBufferView = &b.texelView; break;
        case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
        case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: w.pImageInfo = &b.image; break;
        default:
            buffers[i] = {b.buffer, 0, VK_WHOLE_SIZE};
            w.pBufferInfo = &buffers[i];
            break;
        }
    }
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

} // namespace pf
