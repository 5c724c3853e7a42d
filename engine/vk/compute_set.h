// The descriptor set and pipeline layout of a compute pass: buffers bound in
// order, each as a uniform buffer, a storage buffer or a uniform texel
// buffer — the shape of the cull and physics passes.
#pragma once

#include "engine/vk/resources.h"

#include <span>

namespace pf {

struct ComputeSet {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
};

// Binding b of the set is bindings[b]: a whole buffer for uniform and
// storage buffers, a view for texel buffers.
struct ComputeBinding {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkBufferView view = VK_NULL_HANDLE;
};

// The layouts and the pool are owned by `owner`.
ComputeSet createComputeSet(GpuResources& owner, std::span<const ComputeBinding> bindings);
// buffers[0] is the uniform buffer, the rest storage buffers.
ComputeSet createComputeSet(GpuResources& owner, std::span<const VkBuffer> buffers);
void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set);

} // namespace pf
