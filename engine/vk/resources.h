// Buffers, images, one-shot command submission and the barriers between them.
#pragma once

#include "engine/vk/device.h"

#include <functional>
#include <span>

namespace pf {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // persistently mapped when host visible
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

uint32_t findMemoryType(const GpuContext& ctx, uint32_t typeBits, VkMemoryPropertyFlags flags);

Buffer createBuffer(const GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags);
// A host-visible, coherent, mapped buffer for data the CPU writes or reads.
Buffer createHostBuffer(const GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage);
// A device-local buffer filled through a staging copy.
Buffer createDeviceBufferWithData(const GpuContext& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage);
void destroyBuffer(const GpuContext& ctx, Buffer& buffer);

// A descriptor pool with room for exactly `sets` sets of the layout made of
// `bindings`: the sizes are counted from the bindings, not by hand.
VkDescriptorPool createDescriptorPool(const GpuContext& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings,
                                      uint32_t sets);

// A view of a whole buffer as texels of `format` (`texelBytes` each), for
// shaders that read it as a uniform texel buffer: lavapipe gathers a texel
// for all SIMD lanes at once, where it reads a storage buffer at a
// per-invocation index one float and one lane at a time. Throws when the
// buffer holds more texels than the device's maxTexelBufferElements.
VkBufferView createTexelView(const GpuContext& ctx, const Buffer& buffer, VkFormat format, uint32_t texelBytes);

Image createImage(const GpuContext& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkSampleCountFlagBits samples, VkImageAspectFlags aspect);
void destroyImage(const GpuContext& ctx, Image& image);

// A primary command buffer from the context's pool.
VkCommandBuffer allocateCommandBuffer(const GpuContext& ctx);
// Records with `record`, submits, and waits for the queue to finish.
void submitAndWait(const GpuContext& ctx, const std::function<void(VkCommandBuffer)>& record);

struct ImageTransition {
    VkPipelineStageFlags2 srcStage;
    VkAccessFlags2 srcAccess;
    VkPipelineStageFlags2 dstStage;
    VkAccessFlags2 dstAccess;
    VkImageLayout oldLayout;
    VkImageLayout newLayout;
};
// The barrier for `range` of `image`, to record alone or batched with others.
VkImageMemoryBarrier2 imageMemoryBarrier(VkImage image, const VkImageSubresourceRange& range, const ImageTransition& t);
// Records the barrier for the first mip and layer of `image`.
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, const ImageTransition& t);
// A global memory dependency (synchronization2).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

} // namespace pf
