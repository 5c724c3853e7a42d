// The descriptor set and pipeline layout of a compute pass, made from the
// pass's table (descriptors.h): the shape of the cull and physics passes.
#pragma once

#include "engine/vk/descriptors.h"

namespace pf {

struct ComputeSet {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE; // the set, and push constants when the pass has them
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
};

// Owned by `owner`. `pushConstantBytes` > 0: the compute stage's push
// constant range from offset 0. `laterSets`: the layouts of sets 1, 2, …
// the pipeline layout also has (sets the pass's user binds, such as a
// render target's depth pyramid).
ComputeSet createComputeSet(GpuResources& owner, DescriptorTable table, uint32_t pushConstantBytes = 0,
                            std::span<const VkDescriptorSetLayout> laterSets = {});
void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set);

} // namespace pf
