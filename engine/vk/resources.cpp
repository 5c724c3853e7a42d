#include "engine/vk/resources.h"

#include "engine/vk/vk_check.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {

namespace {

VkDeviceSize texelBytesOf(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R32G32B32A32_UINT: return 16;
    case VK_FORMAT_R32_UINT: return 4;
    default: throw std::invalid_argument("texel views are R32G32B32A32_UINT or R32_UINT");
    }
}

// Memory for a new buffer or image, which is owned after it so destroyed
// before it is freed; when the allocation fails the object is destroyed
// before the error goes on.
template <class Handle>
VkDeviceMemory allocateAndOwn(GpuResources& owner, Handle handle, const VkMemoryRequirements& requirements,
                              VkMemoryPropertyFlags flags,
                              void (*destroy)(VkDevice, Handle, const VkAllocationCallbacks*)) {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    try {
        memory = owner.allocate(requirements, flags);
    } catch (...) {
        destroy(owner.ctx().device, handle, nullptr);
        throw;
    }
    owner.own(handle);
    return memory;
}

} // namespace

Buffer createBuffer(GpuResources& owner, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags) {
    VkDevice device = owner.ctx().device;
    Buffer out;
    out.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device, &info, nullptr, &out.buffer));

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, out.buffer, &req);
    const VkDeviceMemory memory = allocateAndOwn(owner, out.buffer, req, memoryFlags, vkDestroyBuffer);
    VK_CHECK(vkBindBufferMemory(device, out.buffer, memory, 0));
    if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VK_CHECK(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &out.mapped));
    return out;
}

Buffer createHostBuffer(GpuResources& owner, VkDeviceSize size, VkBufferUsageFlags usage) {
    return createBuffer(owner, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

Buffer createDeviceBufferWithData(GpuResources& owner, const void* data, VkDeviceSize size, VkBufferUsageFlags usage) {
    // Vulkan has no empty buffers: an empty array (a species that draws
    // nothing has no joints) gets one zeroed texel, so its descriptors and
    // texel views stay valid.
    const VkDeviceSize bufferSize = std::max<VkDeviceSize>(size, kSmallestBufferBytes);
    GpuResources scratch(owner.ctx());
    Buffer staging = createHostBuffer(scratch, bufferSize, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memset(staging.mapped, 0, bufferSize);
    if (size > 0) std::memcpy(staging.mapped, data, size);
    Buffer out =
        createBuffer(owner, bufferSize, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    submitAndWait(owner.ctx(), [&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bufferSize};
        vkCmdCopyBuffer(cmd, staging.buffer, out.buffer, 1, &region);
    });
    return out;
}

VkBufferView createTexelView(GpuResources& owner, const Buffer& buffer, VkFormat format) {
    const VkDeviceSize texelBytes = texelBytesOf(format);
    const VkDeviceSize texels = buffer.size / texelBytes;
    const uint32_t limit = owner.ctx().properties.limits.maxTexelBufferElements;
    if (texels > limit)
        throw DeviceLimitError("a texel buffer of " + std::to_string(texels) + " texels is more than this device's " +
                               "maxTexelBufferElements (" + std::to_string(limit) + ")");
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.buffer;
    info.format = format;
    info.offset = 0;
    info.range = texels * texelBytes;
    VkBufferView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateBufferView(owner.ctx().device, &info, nullptr, &view));
    return owner.own(view);
}

namespace {

VkImageView createView(GpuResources& owner, VkImage image, VkImageViewType type, VkFormat format,
                       const VkImageSubresourceRange& range) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = type;
    view.format = format;
    view.subresourceRange = range;
    VkImageView out = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(owner.ctx().device, &view, nullptr, &out));
    return owner.own(out);
}

} // namespace

Image createImage(GpuResources& owner, const ImageDesc& desc) {
    VkDevice device = owner.ctx().device;
    Image out;
    out.format = desc.format;
    out.extent = desc.extent;
    out.samples = desc.samples;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = desc.flags;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.extent.width, desc.extent.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.layers;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(device, &info, nullptr, &out.image));

    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, out.image, &req);
    const VkDeviceMemory memory =
        allocateAndOwn(owner, out.image, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, vkDestroyImage);
    VK_CHECK(vkBindImageMemory(device, out.image, memory, 0));

    out.view =
        createView(owner, out.image, desc.viewType, desc.format, {desc.aspect, 0, desc.mipLevels, 0, desc.layers});
    return out;
}

VkImageView createImageView(GpuResources& owner, const Image& image, VkFormat format) {
    return createView(owner, image.image, VK_IMAGE_VIEW_TYPE_2D, format, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1});
}

VkImageView createMipView(GpuResources& owner, const Image& image, uint32_t mip) {
    return createView(owner, image.image, VK_IMAGE_VIEW_TYPE_2D, image.format,
                      {VK_IMAGE_ASPECT_COLOR_BIT, mip, 1, 0, 1});
}

VkImageView createLayerView(GpuResources& owner, const Image& image, uint32_t layer, VkImageAspectFlags aspect) {
    return createView(owner, image.image, VK_IMAGE_VIEW_TYPE_2D, image.format, {aspect, 0, 1, layer, 1});
}

VkSampler createSampler(GpuResources& owner, const VkSamplerCreateInfo& info) {
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(owner.ctx().device, &info, nullptr, &sampler));
    return owner.own(sampler);
}

VkCommandBuffer allocateCommandBuffer(const GpuContext& ctx) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = ctx.commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd));
    return cmd;
}

void submitAndWait(const GpuContext& ctx, const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBuffer cmd = allocateCommandBuffer(ctx);

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));

    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    VK_CHECK(vkQueueSubmit2(ctx.queue, 1, &submit, VK_NULL_HANDLE));
    VK_CHECK(vkQueueWaitIdle(ctx.queue));
    vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
}

VkImageMemoryBarrier2 imageMemoryBarrier(VkImage image, const VkImageSubresourceRange& range,
                                         const ImageTransition& t) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = t.srcStage;
    barrier.srcAccessMask = t.srcAccess;
    barrier.dstStageMask = t.dstStage;
    barrier.dstAccessMask = t.dstAccess;
    barrier.oldLayout = t.oldLayout;
    barrier.newLayout = t.newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = range;
    return barrier;
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, const ImageTransition& t) {
    const VkImageMemoryBarrier2 barrier = imageMemoryBarrier(image, {aspect, 0, 1, 0, 1}, t);
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void transferToComputeBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

void previousFrameReadsBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT |
                      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void clearForSampling(const GpuContext& ctx, const Image& image, VkImageAspectFlags aspect, const VkClearValue& value) {
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        imageBarrier(cmd, image.image, aspect,
                     {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL});
        const VkImageSubresourceRange range{aspect, 0, 1, 0, 1};
        if (aspect == VK_IMAGE_ASPECT_COLOR_BIT)
            vkCmdClearColorImage(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value.color, 1, &range);
        else
            vkCmdClearDepthStencilImage(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value.depthStencil, 1,
                                        &range);
        imageBarrier(cmd, image.image, aspect,
                     {VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    });
}

} // namespace pf
