#include "engine/vk/resources.h"

#include "engine/vk/vk_check.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {

namespace {

VkDeviceMemory allocateMemory(const GpuContext& ctx, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = findMemoryType(ctx, req.memoryTypeBits, flags);
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &memory));
    return memory;
}

} // namespace

uint32_t findMemoryType(const GpuContext& ctx, uint32_t typeBits, VkMemoryPropertyFlags flags) {
    const VkPhysicalDeviceMemoryProperties& props = ctx.memoryProperties;
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw std::runtime_error("no Vulkan memory type with the required properties");
}

Buffer createBuffer(const GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags) {
    Buffer out;
    out.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(ctx.device, &info, nullptr, &out.buffer));

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device, out.buffer, &req);
    out.memory = allocateMemory(ctx, req, memoryFlags);
    VK_CHECK(vkBindBufferMemory(ctx.device, out.buffer, out.memory, 0));
    if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VK_CHECK(vkMapMemory(ctx.device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped));
    return out;
}

Buffer createHostBuffer(const GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage) {
    return createBuffer(ctx, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

Buffer createDeviceBufferWithData(const GpuContext& ctx, const void* data, VkDeviceSize size,
                                  VkBufferUsageFlags usage) {
    Buffer staging = createHostBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, data, size);
    Buffer out = createBuffer(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(cmd, staging.buffer, out.buffer, 1, &region);
    });
    destroyBuffer(ctx, staging);
    return out;
}

void destroyBuffer(const GpuContext& ctx, Buffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(ctx.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(ctx.device, buffer.memory, nullptr);
    buffer = {};
}

VkDescriptorPool createDescriptorPool(const GpuContext& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings,
                                      uint32_t sets) {
    // One pool size per binding: the pool sums them by type.
    std::vector<VkDescriptorPoolSize> sizes;
    for (const VkDescriptorSetLayoutBinding& b : bindings)
        sizes.push_back({b.descriptorType, b.descriptorCount * sets});
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = sets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &info, nullptr, &pool));
    return pool;
}

VkBufferView createTexelView(const GpuContext& ctx, const Buffer& buffer, VkFormat format, uint32_t texelBytes) {
    const VkDeviceSize texels = buffer.size / texelBytes;
    const uint32_t limit = ctx.properties.limits.maxTexelBufferElements;
    if (texels > limit)
        throw std::runtime_error("a texel buffer of " + std::to_string(texels) + " texels is more than this device's " +
                                 "maxTexelBufferElements (" + std::to_string(limit) + ")");
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.buffer;
    info.format = format;
    info.offset = 0;
    info.range = texels * texelBytes;
    VkBufferView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateBufferView(ctx.device, &info, nullptr, &view));
    return view;
}

Image createImage(const GpuContext& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkSampleCountFlagBits samples, VkImageAspectFlags aspect) {
    Image out;
    out.format = format;
    out.extent = extent;
    out.samples = samples;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(ctx.device, &info, nullptr, &out.image));

    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device, out.image, &req);
    out.memory = allocateMemory(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkBindImageMemory(ctx.device, out.image, out.memory, 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = out.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(ctx.device, &view, nullptr, &out.view));
    return out;
}

void destroyImage(const GpuContext& ctx, Image& image) {
    if (image.view) vkDestroyImageView(ctx.device, image.view, nullptr);
    if (image.image) vkDestroyImage(ctx.device, image.image, nullptr);
    if (image.memory) vkFreeMemory(ctx.device, image.memory, nullptr);
    image = {};
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

} // namespace pf
