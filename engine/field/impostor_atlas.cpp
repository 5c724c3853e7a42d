#include "engine/field/impostor_atlas.h"

#include "engine/vk/pipeline.h"
#include "engine/vk/vk_check.h"
#include "shaders/impostor_bake_frag.spv.h"
#include "shaders/impostor_bake_vert.spv.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {

namespace {

constexpr VkFormat kAtlasColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kAtlasNormalFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kBakeDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkSampleCountFlagBits kBakeSamples = VK_SAMPLE_COUNT_4_BIT;

// shaders/impostor_bake.vert's push constants.
struct BakePush {
    glm::vec4 right;  // right axis / half width
    glm::vec4 toView; // view direction / half depth
    glm::vec4 height; // x bottom, y 1 / (top - bottom)
};

uint32_t mipCount(uint32_t size) {
    uint32_t levels = 1;
    while (size > 1) size /= 2, ++levels;
    return levels;
}

Image createAtlasImage(const GpuContext& ctx, uint32_t size, VkFormat format, uint32_t layers, uint32_t mips) {
    Image out;
    out.format = format;
    out.extent = {size, size};
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {size, size, 1};
    info.mipLevels = mips;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    // Destination of the frames' resolves, source and destination of the
    // mip blits, sampled by the billboards.
    info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(ctx.device, &info, nullptr, &out.image));

    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device, out.image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = findMemoryType(ctx, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &out.memory));
    VK_CHECK(vkBindImageMemory(ctx.device, out.image, out.memory, 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = out.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers};
    VK_CHECK(vkCreateImageView(ctx.device, &view, nullptr, &out.view));
    return out;
}

VkImageMemoryBarrier2 atlasBarrier(const Image& image, uint32_t baseMip, uint32_t mips, uint32_t layers,
                                   const ImageTransition& t) {
    return imageMemoryBarrier(image.image, {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mips, 0, layers}, t);
}

void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& images,
                     const VkMemoryBarrier2* memory = nullptr) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = memory ? 1 : 0;
    dep.pMemoryBarriers = memory;
    dep.imageMemoryBarrierCount = uint32_t(images.size());
    dep.pImageMemoryBarriers = images.data();
    vkCmdPipelineBarrier2(cmd, &dep);
}

// Two colour attachments (albedo, normal + depth), depth test, MSAA; the cull
// mode is dynamic: back faces for bark, none for two-sided foliage.
VkPipeline createBakePipeline(VkDevice device, VkPipelineLayout layout, VkShaderModule vertex, VkShaderModule fragment,
                              VkSampleCountFlagBits samples) {
    GraphicsPipelineDesc desc;
    desc.vertex = vertex;
    desc.fragment = fragment;
    desc.layout = layout;
    desc.colorFormat = kAtlasColorFormat;
    desc.secondColorFormat = kAtlasNormalFormat;
    desc.depthFormat = kBakeDepthFormat;
    desc.samples = samples;
    desc.dynamicCullMode = true;
    // The bake projection is a right-handed view with +y at row 0, so
    // triangles counter-clockwise seen from outside stay counter-clockwise
    // in the upright frame.
    desc.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    desc.depthCompare = VK_COMPARE_OP_LESS;
    return createGraphicsPipeline(device, desc);
}

uint32_t quadsOf(BillboardKind kind) {
    switch (kind) {
    case BillboardKind::Single: return 1;
    case BillboardKind::Double: return 2;
    case BillboardKind::Triple: return 3;
    }
    return 2;
}

// 4× MSAA where the device has it for both formats and depth, else none.
VkSampleCountFlagBits bakeSamples(const GpuContext& ctx) {
    const VkPhysicalDeviceLimits& limits = ctx.properties.limits;
    VkSampleCountFlags supported = limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
    return (supported & kBakeSamples) ? kBakeSamples : VK_SAMPLE_COUNT_1_BIT;
}

} // namespace

glm::vec3 impostorViewDirection(uint32_t frame, uint32_t frames) {
    float a = glm::two_pi<float>() * float(frame) / float(frames);
    return {std::sin(a), 0.0f, std::cos(a)};
}

glm::vec3 impostorRightAxis(uint32_t frame, uint32_t frames) {
    float a = glm::two_pi<float>() * float(frame) / float(frames);
    return {std::cos(a), 0.0f, -std::sin(a)};
}

glm::vec4 impostorQuadOf(const gpu::PlantModel& model) {
    float x = std::max(std::abs(model.boxMin.x), std::abs(model.boxMax.x));
    float z = std::max(std::abs(model.boxMin.z), std::abs(model.boxMax.z));
    // An empty model still gets a frame of non-zero size.
    float radius = std::max(std::sqrt(x * x + z * z), 1e-3f);
    float top = std::max(model.boxMax.y, model.boxMin.y + 1e-3f);
    return {radius, model.boxMin.y, top, radius};
}

namespace {

// Reads the coverage of every layer back at mip kOutlineMip (or the last)
// and makes each layer's outline. The atlas is sampled before and after.
std::vector<ImpostorOutline> readOutlines(const GpuContext& ctx, const ImpostorAtlas& atlas) {
    const uint32_t mip = std::min(kOutlineMip, atlas.mipLevels - 1);
    const uint32_t size = std::max(atlas.settings.frameSize >> mip, 1u);
    const VkDeviceSize layerBytes = VkDeviceSize(size) * size * 4;
    Buffer readback = createHostBuffer(ctx, layerBytes * atlas.layers, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        const ImageTransition toSource{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                       VK_ACCESS_2_NONE,
                                       VK_PIPELINE_STAGE_2_COPY_BIT,
                                       VK_ACCESS_2_TRANSFER_READ_BIT,
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        pipelineBarrier(cmd, {atlasBarrier(atlas.color, mip, 1, atlas.layers, toSource)});
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, atlas.layers};
        region.imageExtent = {size, size, 1};
        vkCmdCopyImageToBuffer(cmd, atlas.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1,
                               &region);
        const ImageTransition toSampled{VK_PIPELINE_STAGE_2_COPY_BIT,
                                        VK_ACCESS_2_NONE,
                                        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        pipelineBarrier(cmd, {atlasBarrier(atlas.color, mip, 1, atlas.layers, toSampled)});
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    });
    std::vector<ImpostorOutline> outlines(atlas.layers);
    std::vector<uint8_t> alpha(size_t(size) * size);
    const auto* texels = static_cast<const uint8_t*>(readback.mapped);
    for (uint32_t layer = 0; layer < atlas.layers; ++layer) {
        for (size_t t = 0; t < alpha.size(); ++t) alpha[t] = texels[layer * layerBytes + t * 4 + 3];
        outlines[layer] = impostorOutline(alpha, size, kOutlineMargin);
    }
    destroyBuffer(ctx, readback);
    return outlines;
}

} // namespace

ImpostorAtlas bakeImpostorAtlas(const GpuContext& ctx, PlantModelPool& pool, const Buffer& vertices,
                                const Buffer& indices, const ImpostorSettings& settings) {
    if (settings.frames == 0 || settings.frameSize == 0)
        throw std::runtime_error("impostor atlas: frames and frameSize must be positive");
    const uint64_t layerCount = uint64_t(pool.models.size()) * settings.frames;
    if (layerCount == 0) throw std::runtime_error("impostor atlas: the pool has no models");
    if (layerCount > ctx.properties.limits.maxImageArrayLayers)
        throw std::runtime_error("impostor atlas: " + std::to_string(layerCount) + " layers exceed the device's " +
                                 std::to_string(ctx.properties.limits.maxImageArrayLayers));
    if (settings.frameSize > ctx.properties.limits.maxImageDimension2D)
        throw std::runtime_error("impostor atlas: frameSize " + std::to_string(settings.frameSize) +
                                 " exceeds the device's image limit");

    ImpostorAtlas atlas;
    atlas.settings = settings;
    atlas.layers = uint32_t(layerCount);
    atlas.mipLevels = mipCount(settings.frameSize);
    const uint32_t size = settings.frameSize;
    atlas.color = createAtlasImage(ctx, size, kAtlasColorFormat, atlas.layers, atlas.mipLevels);
    atlas.normalDepth = createAtlasImage(ctx, size, kAtlasNormalFormat, atlas.layers, atlas.mipLevels);

    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = VK_FILTER_LINEAR;
    samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
    VK_CHECK(vkCreateSampler(ctx.device, &samplerInfo, nullptr, &atlas.sampler));

    for (size_t m = 0; m < pool.models.size(); ++m) {
        gpu::PlantModel& model = pool.models[m].gpu;
        model.impostor = {uint32_t(m) * settings.frames, settings.frames, quadsOf(pool.models[m].billboard), 0};
        model.impostorQuad = impostorQuadOf(model);
    }

    // Bake targets reused by every frame (MSAA when the device has it),
    // resolved or copied into the frame's layer after each frame.
    const VkSampleCountFlagBits samples = bakeSamples(ctx);
    const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
    const VkImageUsageFlags targetUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    Image targetColor =
        createImage(ctx, {size, size}, kAtlasColorFormat, targetUsage, samples, VK_IMAGE_ASPECT_COLOR_BIT);
    Image targetNormal =
        createImage(ctx, {size, size}, kAtlasNormalFormat, targetUsage, samples, VK_IMAGE_ASPECT_COLOR_BIT);
    Image depth = createImage(ctx, {size, size}, kBakeDepthFormat,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                              samples, VK_IMAGE_ASPECT_DEPTH_BIT);

    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT};
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setLayoutInfo.bindingCount = 1;
    setLayoutInfo.pBindings = &binding;
    VkDescriptorSetLayout setLayout;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &setLayoutInfo, nullptr, &setLayout));

    VkPushConstantRange pushRange{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(BakePush)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &pushRange;
    VkPipelineLayout pipelineLayout;
    VK_CHECK(vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &pipelineLayout));

    const VkDescriptorPool descriptorPool = createDescriptorPool(ctx, {&binding, 1}, 1);
    VkDescriptorSetAllocateInfo setAlloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    setAlloc.descriptorPool = descriptorPool;
    setAlloc.descriptorSetCount = 1;
    setAlloc.pSetLayouts = &setLayout;
    VkDescriptorSet descriptorSet;
    VK_CHECK(vkAllocateDescriptorSets(ctx.device, &setAlloc, &descriptorSet));
    VkDescriptorBufferInfo vertexInfo{vertices.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = descriptorSet;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &vertexInfo;
    vkUpdateDescriptorSets(ctx.device, 1, &write, 0, nullptr);

    VkShaderModule vertexModule = createShaderModule(ctx.device, spirv_impostor_bake_vert);
    VkShaderModule fragmentModule = createShaderModule(ctx.device, spirv_impostor_bake_frag);
    VkPipeline pipeline = createBakePipeline(ctx.device, pipelineLayout, vertexModule, fragmentModule, samples);

    const uint32_t layers = atlas.layers;
    const uint32_t mips = atlas.mipLevels;
    // All models and frames in one submission.
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        // Level 0 of every layer receives one frame's resolve (or copy);
        // its old contents are discarded.
        const ImageTransition toDestination{VK_PIPELINE_STAGE_2_NONE,
                                            VK_ACCESS_2_NONE,
                                            VK_PIPELINE_STAGE_2_RESOLVE_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                            VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                            VK_IMAGE_LAYOUT_UNDEFINED,
                                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
        pipelineBarrier(cmd, {atlasBarrier(atlas.color, 0, 1, layers, toDestination),
                              atlasBarrier(atlas.normalDepth, 0, 1, layers, toDestination)});

        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout, 0, 1, &descriptorSet, 0, nullptr);
        vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {size, size}};

        // Each frame clears the targets again: the previous frame's resolve
        // reads must be done before (write after read: execution only), and
        // its depth writes before the depth clear (write after write).
        const ImageTransition targetToAttachment{VK_PIPELINE_STAGE_2_RESOLVE_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                                 VK_ACCESS_2_NONE,
                                                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                                 VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                                 VK_IMAGE_LAYOUT_UNDEFINED,
                                                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkImageMemoryBarrier2 depthToAttachment = atlasBarrier(
            depth, 0, 1, 1,
            {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
        depthToAttachment.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        // The frame's attachment writes must land before the resolve reads them.
        const ImageTransition targetToSource{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                             VK_PIPELINE_STAGE_2_RESOLVE_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                             VK_ACCESS_2_TRANSFER_READ_BIT,
                                             VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};

        for (size_t m = 0; m < pool.models.size(); ++m) {
            const PlantModelInfo& model = pool.models[m];
            const glm::vec4 quad = model.gpu.impostorQuad;
            for (uint32_t f = 0; f < settings.frames; ++f) {
                pipelineBarrier(cmd, {atlasBarrier(targetColor, 0, 1, 1, targetToAttachment),
                                      atlasBarrier(targetNormal, 0, 1, 1, targetToAttachment), depthToAttachment});

                VkRenderingAttachmentInfo colors[2]{};
                const VkImageView targets[2] = {targetColor.view, targetNormal.view};
                for (int i = 0; i < 2; ++i) {
                    colors[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
                    colors[i].imageView = targets[i];
                    colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
                    colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
                    colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
                    colors[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}}; // background: coverage 0
                }
                VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
                depthAttachment.imageView = depth.view;
                depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
                depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
                depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
                depthAttachment.clearValue.depthStencil = {1.0f, 0};
                VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
                rendering.renderArea = scissor;
                rendering.layerCount = 1;
                rendering.colorAttachmentCount = 2;
                rendering.pColorAttachments = colors;
                rendering.pDepthAttachment = &depthAttachment;
                vkCmdBeginRendering(cmd, &rendering);
                vkCmdSetViewport(cmd, 0, 1, &viewport);
                vkCmdSetScissor(cmd, 0, 1, &scissor);

                BakePush push;
                push.right = glm::vec4(impostorRightAxis(f, settings.frames) / quad.x, 0.0f);
                push.toView = glm::vec4(impostorViewDirection(f, settings.frames) / quad.w, 0.0f);
                push.height = {quad.y, 1.0f / (quad.z - quad.y), 0.0f, 0.0f};
                vkCmdPushConstants(cmd, pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), &push);
                const VkCullModeFlags cull[kMeshClassCount] = {VK_CULL_MODE_BACK_BIT, VK_CULL_MODE_NONE};
                for (uint32_t c = 0; c < kMeshClassCount; ++c) {
                    const MeshRange& mesh = model.meshes[LOD_FULL][c];
                    if (mesh.indexCount == 0) continue;
                    vkCmdSetCullMode(cmd, cull[c]);
                    vkCmdDrawIndexed(cmd, mesh.indexCount, 1, mesh.firstIndex, int32_t(mesh.vertexOffset), 0);
                }
                vkCmdEndRendering(cmd);

                pipelineBarrier(cmd, {atlasBarrier(targetColor, 0, 1, 1, targetToSource),
                                      atlasBarrier(targetNormal, 0, 1, 1, targetToSource)});
                // A separate resolve rather than a resolve attachment on a
                // layer view: lavapipe resolves those into layer 0.
                const uint32_t layer = model.gpu.impostor.x + f;
                for (const auto& [target, image] :
                     {std::pair{&targetColor, &atlas.color}, std::pair{&targetNormal, &atlas.normalDepth}}) {
                    const VkImageSubresourceLayers src{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                    const VkImageSubresourceLayers dst{VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
                    if (msaa) {
                        VkImageResolve region{src, {}, dst, {}, {size, size, 1}};
                        vkCmdResolveImage(cmd, target->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image->image,
                                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
                    } else {
                        VkImageCopy region{src, {}, dst, {}, {size, size, 1}};
                        vkCmdCopyImage(cmd, target->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image->image,
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
                    }
                }
            }
        }

        // Mips: level k is blitted from level k-1 (premultiplied values
        // average correctly). The resolves into level 0 must be done before
        // the first blit reads it; the other levels hold nothing yet.
        const ImageTransition resolvedToSource{VK_PIPELINE_STAGE_2_RESOLVE_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                               VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                               VK_PIPELINE_STAGE_2_BLIT_BIT,
                                               VK_ACCESS_2_TRANSFER_READ_BIT,
                                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        const ImageTransition emptyToDestination{VK_PIPELINE_STAGE_2_NONE,     VK_ACCESS_2_NONE,
                                                 VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                                 VK_IMAGE_LAYOUT_UNDEFINED,    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
        std::vector<VkImageMemoryBarrier2> toBlit;
        for (const Image* image : {&atlas.color, &atlas.normalDepth}) {
            toBlit.push_back(atlasBarrier(*image, 0, 1, layers, resolvedToSource));
            if (mips > 1) toBlit.push_back(atlasBarrier(*image, 1, mips - 1, layers, emptyToDestination));
        }
        pipelineBarrier(cmd, toBlit);

        for (uint32_t level = 1; level < mips; ++level) {
            const int32_t from = int32_t(std::max(size >> (level - 1), 1u));
            const int32_t to = int32_t(std::max(size >> level, 1u));
            VkImageBlit blit{};
            blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layers};
            blit.srcOffsets[1] = {from, from, 1};
            blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers};
            blit.dstOffsets[1] = {to, to, 1};
            for (const Image* image : {&atlas.color, &atlas.normalDepth})
                vkCmdBlitImage(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image->image,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            // This level is the next blit's source: its writes must land first.
            const ImageTransition writtenToSource{
                VK_PIPELINE_STAGE_2_BLIT_BIT,         VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_BLIT_BIT,         VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
            pipelineBarrier(cmd, {atlasBarrier(atlas.color, level, 1, layers, writtenToSource),
                                  atlasBarrier(atlas.normalDepth, level, 1, layers, writtenToSource)});
        }

        // Every level is now a blit source (the last one also just written):
        // billboards sample them from fragment shaders.
        const ImageTransition toSampled{VK_PIPELINE_STAGE_2_BLIT_BIT,
                                        VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        pipelineBarrier(cmd, {atlasBarrier(atlas.color, 0, mips, layers, toSampled),
                              atlasBarrier(atlas.normalDepth, 0, mips, layers, toSampled)});
    });

    vkDestroyPipeline(ctx.device, pipeline, nullptr);
    vkDestroyShaderModule(ctx.device, vertexModule, nullptr);
    vkDestroyShaderModule(ctx.device, fragmentModule, nullptr);
    vkDestroyDescriptorPool(ctx.device, descriptorPool, nullptr);
    vkDestroyPipelineLayout(ctx.device, pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(ctx.device, setLayout, nullptr);
    destroyImage(ctx, depth);
    destroyImage(ctx, targetNormal);
    destroyImage(ctx, targetColor);
    atlas.outlines = readOutlines(ctx, atlas);
    return atlas;
}

void destroyImpostorAtlas(const GpuContext& ctx, ImpostorAtlas& atlas) {
    if (atlas.sampler) vkDestroySampler(ctx.device, atlas.sampler, nullptr);
    destroyImage(ctx, atlas.color);
    destroyImage(ctx, atlas.normalDepth);
    atlas = {};
}

MeshRange appendBillboardMesh(PlantModelPool& pool, uint32_t quads) {
    if (quads < 1 || quads > 3) throw std::runtime_error("billboard mesh: quads must be 1, 2 or 3");
    MeshRange range;
    range.firstIndex = uint32_t(pool.indices.size());
    range.indexCount = 3 * (kOutlineCorners - 2) * quads;
    range.vertexOffset = uint32_t(pool.vertices.size());
    for (uint32_t q = 0; q < quads; ++q) {
        for (uint32_t c = 0; c < kOutlineCorners; ++c) {
            gpu::FieldVertex v{};
            v.position = {float(c), 0.0f, float(q), 0.0f};
            v.normal = {0.0f, 0.0f, 1.0f, 0.0f};
            v.albedo = {1.0f, 1.0f, 1.0f, SURFACE_LEAF};
            pool.vertices.push_back(v);
        }
        // A fan: the outline is convex.
        for (uint32_t c = 1; c + 1 < kOutlineCorners; ++c)
            for (uint32_t i : {0u, c, c + 1}) pool.indices.push_back(kOutlineCorners * q + i);
    }
    return range;
}

} // namespace pf
