// Buffers, images, one-shot command submission and the barriers between them.
#pragma once

#include "engine/vk/gpu_resources.h"

#include <functional>

namespace pf {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // persistently mapped when host visible
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE; // of every mip level and layer
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

// Every buffer, view, image and sampler below is owned by `owner`, which
// destroys it.
Buffer createBuffer(GpuResources& owner, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags);
// A host-visible, coherent, mapped buffer for data the CPU writes or reads.
Buffer createHostBuffer(GpuResources& owner, VkDeviceSize size, VkBufferUsageFlags usage);
// A device-local buffer filled through a staging copy; `size` 0 (data may
// then be null) gives kSmallestBufferBytes of zeros.
inline constexpr VkDeviceSize kSmallestBufferBytes = 16;
Buffer createDeviceBufferWithData(GpuResources& owner, const void* data, VkDeviceSize size, VkBufferUsageFlags usage);

// A view of a whole buffer as texels of `format`, R32G32B32A32_UINT (16
// bytes: a struct of N vec4/uvec4 members is N texels, its *_TEXELS stride
// in shaders/*_layouts.h) or R32_UINT, for shaders that read it as a
// uniform texel buffer: lavapipe gathers a texel for all SIMD lanes at once,
// where it reads a storage buffer at a per-invocation index one float and
// one lane at a time. Throws when the buffer holds more texels than the
// device's maxTexelBufferElements.
VkBufferView createTexelView(GpuResources& owner, const Buffer& buffer, VkFormat format);

struct ImageDesc {
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    uint32_t mipLevels = 1;
    uint32_t layers = 1;
    VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D;
    VkImageCreateFlags flags = 0; // VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT: views of other formats (createImageView)
};
// A device-local 2D image (or array) and its view.
Image createImage(GpuResources& owner, const ImageDesc& desc);
// Another view of a colour image's first mip and layer, in `format` of the
// same texel size: the image was made with VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT.
VkImageView createImageView(GpuResources& owner, const Image& image, VkFormat format);

// A view of one mip level (first layer) of a colour image, in its format.
VkImageView createMipView(GpuResources& owner, const Image& image, uint32_t mip);
// A view of one layer (first mip level) of an image array, in its format.
VkImageView createLayerView(GpuResources& owner, const Image& image, uint32_t layer, VkImageAspectFlags aspect);

VkSampler createSampler(GpuResources& owner, const VkSamplerCreateInfo& info);

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

// Clears a one-level image (colour, or depth with VK_IMAGE_ASPECT_DEPTH_BIT)
// and leaves it in SHADER_READ_ONLY_OPTIMAL for fragment shaders, waiting
// for it: an image the shaders may sample before any pass writes it.
void clearForSampling(const GpuContext& ctx, const Image& image, VkImageAspectFlags aspect, const VkClearValue& value);
// A global memory dependency (synchronization2).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);
// Transfer writes (fills, updates) made visible to compute shaders that read
// them or add to them with atomics: the counters every GPU-driven pass zeroes.
void transferToComputeBarrier(VkCommandBuffer cmd);
// A per-frame compute pass about to rewrite its buffers: the previous frame
// (or an earlier phase) may still dispatch or draw indirectly from them,
// read them in vertex or compute shaders or copy them (write-after-read),
// and its compute writes must be visible to this pass's fills and shaders.
void previousFrameReadsBarrier(VkCommandBuffer cmd);

} // namespace pf
