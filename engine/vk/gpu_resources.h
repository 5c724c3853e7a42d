// The owner of Vulkan objects: whatever creates a buffer, image, view,
// sampler, pipeline, layout or pool hands it to one GpuResources, which
// destroys everything it was given, newest first, in one place, and counts
// the device memory it holds. A renderer owns one for all its passes; a
// load-time step keeps its scratch objects in a local one.
#pragma once

#include "engine/vk/device.h"

#include <cstdint>
#include <vector>

namespace pf {

template <class Handle>
constexpr VkObjectType kOwnedObjectType = VK_OBJECT_TYPE_UNKNOWN;
template <>
constexpr VkObjectType kOwnedObjectType<VkBuffer> = VK_OBJECT_TYPE_BUFFER;
template <>
constexpr VkObjectType kOwnedObjectType<VkBufferView> = VK_OBJECT_TYPE_BUFFER_VIEW;
template <>
constexpr VkObjectType kOwnedObjectType<VkImage> = VK_OBJECT_TYPE_IMAGE;
template <>
constexpr VkObjectType kOwnedObjectType<VkImageView> = VK_OBJECT_TYPE_IMAGE_VIEW;
template <>
constexpr VkObjectType kOwnedObjectType<VkSampler> = VK_OBJECT_TYPE_SAMPLER;
template <>
constexpr VkObjectType kOwnedObjectType<VkShaderModule> = VK_OBJECT_TYPE_SHADER_MODULE;
template <>
constexpr VkObjectType kOwnedObjectType<VkPipeline> = VK_OBJECT_TYPE_PIPELINE;
template <>
constexpr VkObjectType kOwnedObjectType<VkPipelineLayout> = VK_OBJECT_TYPE_PIPELINE_LAYOUT;
template <>
constexpr VkObjectType kOwnedObjectType<VkDescriptorSetLayout> = VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT;
template <>
constexpr VkObjectType kOwnedObjectType<VkDescriptorPool> = VK_OBJECT_TYPE_DESCRIPTOR_POOL;

class GpuResources {
public:
    GpuResources() = default; // owns nothing and can own nothing until assigned one made for a context
    explicit GpuResources(const GpuContext& ctx) : ctx_(&ctx) {}
    GpuResources(GpuResources&& other) noexcept;
    GpuResources& operator=(GpuResources&& other) noexcept; // destroys what this owned first
    GpuResources(const GpuResources&) = delete;
    GpuResources& operator=(const GpuResources&) = delete;
    ~GpuResources() { destroy(); }

    const GpuContext& ctx() const { return *ctx_; }

    // Registers `handle` to be destroyed with the rest; returns it.
    template <class Handle>
    Handle own(Handle handle) {
        static_assert(kOwnedObjectType<Handle> != VK_OBJECT_TYPE_UNKNOWN, "GpuResources cannot destroy this handle");
        owned_.push_back({kOwnedObjectType<Handle>, reinterpret_cast<uint64_t>(handle), 0});
        return handle;
    }
    // Allocates device memory that is freed with the rest and counted by bytes().
    VkDeviceMemory allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags flags);

    // Device memory held: every allocation's size, padding included.
    VkDeviceSize bytes() const;
    // Destroys everything owned, newest first (the caller makes sure the GPU
    // no longer uses it); owns nothing afterwards. The destructor calls it.
    void destroy();

private:
    struct Owned {
        VkObjectType type;
        uint64_t handle;
        VkDeviceSize bytes; // device memory only
    };
    const GpuContext* ctx_ = nullptr;
    std::vector<Owned> owned_; // in creation order
};

} // namespace pf
