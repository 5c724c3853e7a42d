#include "engine/vk/gpu_resources.h"

#include "engine/vk/vk_check.h"
#include "lsystem/common/memory_budget.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace pf {
namespace {

uint32_t findMemoryType(const GpuContext& ctx, uint32_t typeBits, VkMemoryPropertyFlags flags) {
    const VkPhysicalDeviceMemoryProperties& props = ctx.memoryProperties;
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw std::runtime_error("no Vulkan memory type with the required properties");
}

template <class Handle>
Handle as(uint64_t handle) {
    return reinterpret_cast<Handle>(handle);
}

} // namespace

GpuResources::GpuResources(GpuResources&& other) noexcept : ctx_(other.ctx_), owned_(std::exchange(other.owned_, {})) {}

GpuResources& GpuResources::operator=(GpuResources&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        owned_ = std::exchange(other.owned_, {});
    }
    return *this;
}

VkDeviceMemory GpuResources::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = findMemoryType(*ctx_, requirements.memoryTypeBits, flags);
    // Asked before the driver: lavapipe aborts on an allocation beyond its heap.
    const VkMemoryHeap& heap =
        ctx_->memoryProperties.memoryHeaps[ctx_->memoryProperties.memoryTypes[info.memoryTypeIndex].heapIndex];
    if (requirements.size > heap.size)
        throw DeviceLimitError("the GPU would need " + std::to_string(requirements.size >> 20) +
                               " MiB in one allocation, more than its memory heap of " +
                               std::to_string(heap.size >> 20) + " MiB");
    // A CPU device's memory is the machine's: counted, all of it together, against the memory budget.
    const bool hostMemory = ctx_->properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    if (hostMemory)
        lsys::need(lsys::MemoryBudget{ctx_->hostMemoryLimit},
                   std::string("device memory (") + ctx_->properties.deviceName +
                       " is the CPU: its memory is the host's)",
                   lsys::bytesPlus(*ctx_->hostMemoryHeld, requirements.size));
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(ctx_->device, &info, nullptr, &memory));
    owned_.push_back({VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<uint64_t>(memory), requirements.size});
    if (hostMemory) *ctx_->hostMemoryHeld += requirements.size;
    return memory;
}

VkDeviceSize GpuResources::bytes() const {
    VkDeviceSize total = 0;
    for (const Owned& o : owned_) total += o.bytes;
    return total;
}

void GpuResources::destroy() {
    for (auto it = owned_.rbegin(); it != owned_.rend(); ++it) {
        VkDevice device = ctx_->device;
        switch (it->type) {
        case VK_OBJECT_TYPE_DEVICE_MEMORY:
            vkFreeMemory(device, as<VkDeviceMemory>(it->handle), nullptr);
            if (ctx_->properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) *ctx_->hostMemoryHeld -= it->bytes;
            break;
        case VK_OBJECT_TYPE_BUFFER: vkDestroyBuffer(device, as<VkBuffer>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_BUFFER_VIEW: vkDestroyBufferView(device, as<VkBufferView>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_IMAGE: vkDestroyImage(device, as<VkImage>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_IMAGE_VIEW: vkDestroyImageView(device, as<VkImageView>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_SAMPLER: vkDestroySampler(device, as<VkSampler>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_SHADER_MODULE:
            vkDestroyShaderModule(device, as<VkShaderModule>(it->handle), nullptr);
            break;
        case VK_OBJECT_TYPE_PIPELINE: vkDestroyPipeline(device, as<VkPipeline>(it->handle), nullptr); break;
        case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
            vkDestroyPipelineLayout(device, as<VkPipelineLayout>(it->handle), nullptr);
            break;
        case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
            vkDestroyDescriptorSetLayout(device, as<VkDescriptorSetLayout>(it->handle), nullptr);
            break;
        case VK_OBJECT_TYPE_DESCRIPTOR_POOL:
            vkDestroyDescriptorPool(device, as<VkDescriptorPool>(it->handle), nullptr);
            break;
        default: break; // own() accepts only the types above
        }
    }
    owned_.clear();
}

} // namespace pf
