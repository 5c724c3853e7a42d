// The impostor atlas's images (impostor_atlas_images.h).
#include "engine/field/impostor_atlas_images.h"

#include "shaders/shared/impostor_frame.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {
namespace {

uint32_t mipCount(uint32_t size) {
    uint32_t levels = 1;
    while (size > 1) size /= 2, ++levels;
    return levels;
}

uint32_t quadsOf(BillboardKind kind) {
    switch (kind) {
    case BillboardKind::Single: return 1;
    case BillboardKind::Double: return 2;
    case BillboardKind::Triple: return 3;
    }
    return 2;
}

// Destination of the frames' filtered targets, source and destination of the mip
// blits, sampled by the billboards.
Image createAtlasImage(GpuResources& owner, uint32_t size, VkFormat format, uint32_t layers, uint32_t mips) {
    return createImage(
        owner, {.extent = {size, size},
                .format = format,
                .usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                .mipLevels = mips,
                .layers = layers,
                .viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY});
}

} // namespace

VkImageMemoryBarrier2 atlasBarrier(const Image& image, uint32_t baseMip, uint32_t mips, uint32_t layers,
                                   const ImageTransition& t) {
    return imageMemoryBarrier(image.image, {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mips, 0, layers}, t);
}

VkImageBlit halvingBlit(uint32_t side, const VkImageSubresourceLayers& from, const VkImageSubresourceLayers& to) {
    const int32_t source = int32_t(std::max(side, 1u)), destination = int32_t(std::max(side / 2, 1u));
    VkImageBlit blit{};
    blit.srcSubresource = from;
    blit.srcOffsets[1] = {source, source, 1};
    blit.dstSubresource = to;
    blit.dstOffsets[1] = {destination, destination, 1};
    return blit;
}

void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& images) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = uint32_t(images.size());
    dep.pImageMemoryBarriers = images.data();
    vkCmdPipelineBarrier2(cmd, &dep);
}

uint32_t impostorModelCapacity(const GpuContext& ctx, const ImpostorSettings& settings) {
    if (settings.frames == 0 || settings.frameSize == 0 || settings.shadowFrameSize == 0)
        throw std::runtime_error("impostor atlas: frames, frameSize and shadowFrameSize must be positive");
    if (std::max(settings.frameSize, settings.shadowFrameSize) > ctx.properties.limits.maxImageDimension2D)
        throw std::runtime_error("impostor atlas: frameSize " + std::to_string(settings.frameSize) +
                                 " or shadowFrameSize " + std::to_string(settings.shadowFrameSize) +
                                 " exceeds the device's image limit");
    return ctx.properties.limits.maxImageArrayLayers / (settings.frames * IMPOSTOR_RINGS);
}

uint32_t atlasLayers(const std::vector<uint32_t>& sources, const ImpostorSettings& settings) {
    uint32_t baked = 0;
    for (size_t m = 0; m < sources.size(); ++m) baked += sources[m] == m;
    if (baked == 0) throw std::runtime_error("impostor atlas: the pool has no models");
    return baked * settings.frames * IMPOSTOR_RINGS;
}

ImpostorAtlas createAtlas(GpuResources& owner, const ImpostorSettings& settings, uint32_t layers) {
    ImpostorAtlas atlas;
    atlas.settings = settings;
    atlas.layers = layers;
    atlas.shadowLayers = layers / IMPOSTOR_RINGS;
    atlas.mipLevels = mipCount(settings.frameSize);
    atlas.color = createAtlasImage(owner, settings.frameSize, kAtlasColorFormat, layers, atlas.mipLevels);
    atlas.normalDepth = createAtlasImage(owner, settings.frameSize, kAtlasNormalFormat, layers, atlas.mipLevels);
    atlas.shadowMipLevels = mipCount(settings.shadowFrameSize);
    atlas.shadow = createAtlasImage(owner, settings.shadowFrameSize, kShadowFrameFormat, atlas.shadowLayers,
                                    atlas.shadowMipLevels);

    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = VK_FILTER_LINEAR;
    samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
    atlas.sampler = createSampler(owner, samplerInfo);
    return atlas;
}

void assignImpostorLayers(PlantModelPool& pool, const ImpostorSettings& settings,
                          const std::vector<uint32_t>& sources) {
    uint32_t baked = 0;
    for (size_t m = 0; m < pool.models.size(); ++m) {
        gpu::PlantModel& model = pool.models[m].gpu;
        if (sources[m] != m) {
            // A source comes first among its species' variants, so it is assigned already.
            const gpu::PlantModel& source = pool.models[sources[m]].gpu;
            model.impostor = source.impostor;
            model.impostorQuad = source.impostorQuad;
            continue;
        }
        const uint32_t shadowFirst = baked++ * settings.frames;
        model.impostor = {shadowFirst * IMPOSTOR_RINGS, settings.frames, quadsOf(pool.models[m].billboard),
                          shadowFirst};
        model.impostorQuad = impostorQuadOf(model);
    }
}

void recordMipChain(VkCommandBuffer cmd, std::initializer_list<const Image*> images, uint32_t size, uint32_t mips,
                    uint32_t layers) {
    // The frames' blits into level 0 must be done before the first mip blit
    // reads it; the other levels hold nothing yet.
    const ImageTransition bakedToSource{VK_PIPELINE_STAGE_2_BLIT_BIT,         VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                        VK_PIPELINE_STAGE_2_BLIT_BIT,         VK_ACCESS_2_TRANSFER_READ_BIT,
                                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    const ImageTransition emptyToDestination{VK_PIPELINE_STAGE_2_NONE,     VK_ACCESS_2_NONE,
                                             VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                             VK_IMAGE_LAYOUT_UNDEFINED,    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    std::vector<VkImageMemoryBarrier2> toBlit;
    for (const Image* image : images) {
        toBlit.push_back(atlasBarrier(*image, 0, 1, layers, bakedToSource));
        if (mips > 1) toBlit.push_back(atlasBarrier(*image, 1, mips - 1, layers, emptyToDestination));
    }
    pipelineBarrier(cmd, toBlit);

    for (uint32_t level = 1; level < mips; ++level) {
        const VkImageBlit blit = halvingBlit(size >> (level - 1), {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layers},
                                             {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers});
        for (const Image* image : images)
            vkCmdBlitImage(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image->image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        // This level is the next blit's source: its writes must land first.
        const ImageTransition writtenToSource{
            VK_PIPELINE_STAGE_2_BLIT_BIT,  VK_ACCESS_2_TRANSFER_WRITE_BIT,       VK_PIPELINE_STAGE_2_BLIT_BIT,
            VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        std::vector<VkImageMemoryBarrier2> written;
        for (const Image* image : images) written.push_back(atlasBarrier(*image, level, 1, layers, writtenToSource));
        pipelineBarrier(cmd, written);
    }

    // Every level is now a blit source (the last one also just written):
    // billboards sample them from fragment shaders.
    const ImageTransition toSampled{VK_PIPELINE_STAGE_2_BLIT_BIT,
                                    VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    std::vector<VkImageMemoryBarrier2> sampled;
    for (const Image* image : images) sampled.push_back(atlasBarrier(*image, 0, mips, layers, toSampled));
    pipelineBarrier(cmd, sampled);
}

std::vector<ImpostorOutline> readOutlines(const GpuContext& ctx, const ImpostorAtlas& atlas) {
    const uint32_t mip = std::min(kOutlineMip, atlas.mipLevels - 1);
    const uint32_t size = std::max(atlas.settings.frameSize >> mip, 1u);
    const VkDeviceSize layerBytes = VkDeviceSize(size) * size * 4;
    GpuResources scratch(ctx);
    Buffer readback = createHostBuffer(scratch, layerBytes * atlas.layers, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
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
    return outlines;
}

} // namespace pf
