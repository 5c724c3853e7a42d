// The descriptor set and pipeline layout of a compute pass whose bindings
// are one uniform buffer (binding 0) followed by storage buffers, in order —
// the shape of the cull and physics passes.
#pragma once

#include "engine/resources.h"

#include <span>

namespace pf {

struct ComputeSet {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
};

// buffers[0] is the uniform buffer, the rest storage buffers (whole ranges).
ComputeSet createComputeSet(const GpuContext& ctx, std::span<const VkBuffer> buffers);
void destroyComputeSet(const GpuContext& ctx, ComputeSet& set);
void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set);

} // namespace pf
