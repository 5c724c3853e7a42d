// Descriptor sets made from one table per set: each entry names a binding,
// its descriptor type, the stages that read it and the resource bound there,
// and both the set layout and the writes are made from the same entries, so
// a binding's number, type and resource are said once.
#pragma once

#include "engine/vk/resources.h"

#include <span>
#include <vector>

namespace pf {

struct DescriptorBinding {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    VkShaderStageFlags stages = 0;
    // The resource, by type: the whole buffer (uniform and storage buffers),
    // a view (uniform texel buffers), or a sampled image.
    VkBuffer buffer = VK_NULL_HANDLE;
    VkBufferView texelView = VK_NULL_HANDLE;
    VkDescriptorImageInfo image{};
};

DescriptorBinding uniformBuffer(uint32_t binding, VkShaderStageFlags stages, const Buffer& buffer);
DescriptorBinding storageBuffer(uint32_t binding, VkShaderStageFlags stages, const Buffer& buffer);
DescriptorBinding texelBuffer(uint32_t binding, VkShaderStageFlags stages, VkBufferView view);
// A combined image sampler, read in SHADER_READ_ONLY_OPTIMAL.
DescriptorBinding sampledImage(uint32_t binding, VkShaderStageFlags stages, VkSampler sampler, VkImageView view);

// A storage image, read and written in GENERAL.
DescriptorBinding storageImage(uint32_t binding, VkShaderStageFlags stages, VkImageView view);

using DescriptorTable = std::span<const DescriptorBinding>;

// What follows is owned by `owner`.
VkDescriptorSetLayout createSetLayout(GpuResources& owner, DescriptorTable table);
// Room for exactly `sets` sets of the table's layout: the sizes are counted
// from its entries.
VkDescriptorPool createDescriptorPool(GpuResources& owner, DescriptorTable table, uint32_t sets);
// One set of `layout` per table, in a pool of their own, each written from
// its table. The tables share the layout's bindings and differ only in
// their resources.
std::vector<VkDescriptorSet> createSets(GpuResources& owner, VkDescriptorSetLayout layout,
                                        std::span<const DescriptorTable> tables);
VkDescriptorSet createSet(GpuResources& owner, VkDescriptorSetLayout layout, DescriptorTable table);
// A pipeline layout of one set and, when push.size > 0, one push constant range.
VkPipelineLayout createPipelineLayout(GpuResources& owner, VkDescriptorSetLayout setLayout,
                                      VkPushConstantRange push = {});
// The same over sets 0, 1, … in order.
VkPipelineLayout createPipelineLayout(GpuResources& owner, std::span<const VkDescriptorSetLayout> setLayouts,
                                      VkPushConstantRange push = {});

// Writes every entry of the table into `set`.
void writeSet(VkDevice device, VkDescriptorSet set, DescriptorTable table);

} // namespace pf
