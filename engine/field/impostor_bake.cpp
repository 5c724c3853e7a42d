// The impostor bake (impostor_atlas.h): every model drawn from every frame
// direction into targets of twice the frame's side, a ring of frames at a
// time, each ring filtered down 2:1 into its atlas layers (2×2
// supersampling), then from every shadow frame direction into its
// coverage-only targets and the shadow frames' layers, the mip chains
// blitted, and the outlines read back.
#include "engine/field/impostor_atlas.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "shaders/impostor_bake_frag.spv.h"
#include "shaders/impostor_bake_vert.spv.h"
#include "shaders/impostor_shadow_bake_frag.spv.h"
#include "shaders/shared/impostor_frame.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {
namespace {

constexpr VkFormat kAtlasColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kAtlasNormalFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kShadowFrameFormat = VK_FORMAT_R8G8_UNORM;
constexpr VkFormat kBakeDepthFormat = VK_FORMAT_D32_SFLOAT;
// Frames are drawn at this many times the frame's side, one sample a pixel,
// and filtered down to it: 2×2 supersampling. On lavapipe it takes about two
// thirds of the time of 4× MSAA at the frame's side, whose per-sample coverage
// and resolve cost more than shading four times the pixels.
constexpr uint32_t kBakeSupersampling = 2;

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

VkImageMemoryBarrier2 atlasBarrier(const Image& image, uint32_t baseMip, uint32_t mips, uint32_t layers,
                                   const ImageTransition& t) {
    return imageMemoryBarrier(image.image, {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mips, 0, layers}, t);
}

// A linear blit halving a square of `side` texels (none below 1) from the
// `from` layers into the `to` layers: every destination texel is sampled at
// the corner its 2×2 source texels share, with weight 1/4 each, a box filter
// of the premultiplied values and the coverage. The frames' 2:1 filtering
// and the mip chains both use it.
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

// The colour images' layer count (every model's rings of frames), after
// checking the atlas fits the device.
uint32_t atlasLayers(const GpuContext& ctx, const PlantModelPool& pool, const ImpostorSettings& settings) {
    if (settings.frames == 0 || settings.frameSize == 0)
        throw std::runtime_error("impostor atlas: frames and frameSize must be positive");
    const uint64_t layerCount = uint64_t(pool.models.size()) * settings.frames * IMPOSTOR_RINGS;
    if (layerCount == 0) throw std::runtime_error("impostor atlas: the pool has no models");
    if (layerCount > ctx.properties.limits.maxImageArrayLayers)
        throw std::runtime_error(
            "the impostor atlas would need " + std::to_string(layerCount) + " layers (" +
            std::to_string(pool.models.size()) + " plant models, the scene's variants of every species, times " +
            std::to_string(settings.frames * IMPOSTOR_RINGS) + " views), more than this device's " +
            std::to_string(ctx.properties.limits.maxImageArrayLayers) + ": give the species fewer \"variants\"");
    if (settings.shadowFrameSize == 0) throw std::runtime_error("impostor atlas: shadowFrameSize must be positive");
    if (std::max(settings.frameSize, settings.shadowFrameSize) > ctx.properties.limits.maxImageDimension2D)
        throw std::runtime_error("impostor atlas: frameSize " + std::to_string(settings.frameSize) +
                                 " or shadowFrameSize " + std::to_string(settings.shadowFrameSize) +
                                 " exceeds the device's image limit");
    return uint32_t(layerCount);
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

// The three images with their full mip chains (the shadow frames one ring
// per model), and the billboards' sampler.
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

// Each model's first colour and shadow layers, frames, quads per billboard
// and baked box.
void assignImpostorLayers(PlantModelPool& pool, const ImpostorSettings& settings) {
    for (size_t m = 0; m < pool.models.size(); ++m) {
        gpu::PlantModel& model = pool.models[m].gpu;
        const uint32_t shadowFirst = uint32_t(m) * settings.frames;
        model.impostor = {shadowFirst * IMPOSTOR_RINGS, settings.frames, quadsOf(pool.models[m].billboard),
                          shadowFirst};
        model.impostorQuad = impostorQuadOf(model);
    }
}

// An image every frame of a ring is drawn into, one layer each,
// kBakeSupersampling times the frame's side, and a view of each layer. A
// ring's frames are drawn one after the other and filtered into their atlas
// layers together: the filtering waits for the drawing it reads, and on
// lavapipe waiting after every frame keeps the rasteriser's threads and the
// thread that bins the next frame's triangles from working at the same time
// (with a wait per ring, a capture of the default scene took 0.90 of the
// time).
struct BakeTarget {
    Image image;
    std::vector<VkImageView> layers;
};

BakeTarget createBakeTarget(GpuResources& owner, uint32_t side, VkFormat format, uint32_t layers) {
    const bool depth = format == kBakeDepthFormat;
    const VkImageAspectFlags aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    BakeTarget target;
    target.image = createImage(owner, {.extent = {side, side},
                                       .format = format,
                                       .usage = depth ? VkImageUsageFlags{VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                                          VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT}
                                                      : VkImageUsageFlags{VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                                       .aspect = aspect,
                                       .layers = layers,
                                       .viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY});
    for (uint32_t layer = 0; layer < layers; ++layer)
        target.layers.push_back(createLayerView(owner, target.image, layer, aspect));
    return target;
}

struct BakeTargets {
    BakeTarget color;
    BakeTarget normalDepth;
    BakeTarget depth;
    BakeTarget shadow; // coverage and depth from the sun
    BakeTarget shadowDepth;
    uint32_t size = 0;       // the colour targets' side
    uint32_t shadowSize = 0; // the shadow targets' side
};

BakeTargets createBakeTargets(GpuResources& owner, const ImpostorSettings& settings) {
    BakeTargets targets;
    targets.size = settings.frameSize * kBakeSupersampling;
    targets.shadowSize = settings.shadowFrameSize * kBakeSupersampling;
    const uint32_t frames = settings.frames;
    targets.color = createBakeTarget(owner, targets.size, kAtlasColorFormat, frames);
    targets.normalDepth = createBakeTarget(owner, targets.size, kAtlasNormalFormat, frames);
    targets.depth = createBakeTarget(owner, targets.size, kBakeDepthFormat, frames);
    targets.shadow = createBakeTarget(owner, targets.shadowSize, kShadowFrameFormat, frames);
    targets.shadowDepth = createBakeTarget(owner, targets.shadowSize, kBakeDepthFormat, frames);
    return targets;
}

// shaders/impostor_bake.vert reading the vertex pool, with the frame's
// view as push constants, and the cull mode dynamic. The colour frames'
// pipeline (impostor_bake.frag): two colour attachments (albedo, normal +
// depth), depth test, back faces culled for bark, none for two-sided
// foliage. The shadow frames' (impostor_shadow_bake.frag): one attachment
// of coverage and the nearest depth from the sun, depth test, both sides of
// everything, as the shadow passes cast.
struct BakePipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipeline shadowPipeline = VK_NULL_HANDLE;
};

BakePipeline createBakePipeline(GpuResources& owner, const Buffer& vertices) {
    const DescriptorBinding table[] = {
        storageBuffer(IMPOSTOR_BAKE_BINDING_VERTICES, VK_SHADER_STAGE_VERTEX_BIT, vertices)};
    const VkDescriptorSetLayout setLayout = createSetLayout(owner, table);
    BakePipeline bake;
    bake.set = createSet(owner, setLayout, table);
    bake.layout =
        createPipelineLayout(owner, setLayout, {VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(gpu::ImpostorBakePush)});

    GpuResources modules(owner.ctx());
    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(modules, spirv_impostor_bake_vert);
    desc.fragment = createShaderModule(modules, spirv_impostor_bake_frag);
    desc.layout = bake.layout;
    desc.colorFormat = kAtlasColorFormat;
    desc.secondColorFormat = kAtlasNormalFormat;
    desc.depthFormat = kBakeDepthFormat;
    desc.dynamicCullMode = true;
    // The bake projection is a right-handed view with +y at row 0, so
    // triangles counter-clockwise seen from outside stay counter-clockwise
    // in the upright frame.
    desc.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    desc.depthCompare = VK_COMPARE_OP_LESS;
    bake.pipeline = createGraphicsPipeline(owner, desc);

    desc.fragment = createShaderModule(modules, spirv_impostor_shadow_bake_frag);
    desc.colorFormat = kShadowFrameFormat;
    desc.secondColorFormat = VK_FORMAT_UNDEFINED;
    bake.shadowPipeline = createGraphicsPipeline(owner, desc);
    return bake;
}

// Every layer of a ring's targets made ready to be cleared and drawn.
void prepareBakeRing(VkCommandBuffer cmd, std::initializer_list<const BakeTarget*> colors, const BakeTarget& depth,
                     uint32_t frames) {
    // The previous ring's filtering reads must be done before its layers
    // are cleared again (write after read: execution only), and its depth
    // writes before the depth clears (write after write).
    const ImageTransition toAttachment{VK_PIPELINE_STAGE_2_BLIT_BIT,
                                       VK_ACCESS_2_NONE,
                                       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                       VK_IMAGE_LAYOUT_UNDEFINED,
                                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkImageMemoryBarrier2 depthToAttachment =
        atlasBarrier(depth.image, 0, 1, frames,
                     {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    depthToAttachment.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    std::vector<VkImageMemoryBarrier2> barriers{depthToAttachment};
    for (const BakeTarget* color : colors) barriers.push_back(atlasBarrier(color->image, 0, 1, frames, toAttachment));
    pipelineBarrier(cmd, barriers);
}

// Clears layer `layer` of the targets (colour attachments and depth,
// `size`²) and begins rendering into it.
void beginBakeFrame(VkCommandBuffer cmd, std::initializer_list<const BakeTarget*> colors, const BakeTarget& depthTarget,
                    uint32_t size, uint32_t layer) {
    std::vector<VkRenderingAttachmentInfo> attachments;
    for (const BakeTarget* color : colors) {
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = color->layers[layer];
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}}; // background: coverage 0
        attachments.push_back(a);
    }
    const VkRenderingAttachmentInfo depth =
        clearedDepthAttachment(depthTarget.layers[layer], VK_ATTACHMENT_STORE_OP_DONT_CARE);
    const VkRect2D area{{0, 0}, {size, size}};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = area;
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = uint32_t(attachments.size());
    rendering.pColorAttachments = attachments.data();
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);
    const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
}

// The orthographic view with these axes mapping [-half, half] about
// `centre` to the frame (ImpostorBakePush).
gpu::ImpostorBakePush bakeView(glm::vec3 centre, glm::vec3 right, glm::vec3 up, glm::vec3 toView, glm::vec3 half) {
    auto axis = [&](glm::vec3 a, float h) { return glm::vec4(a / h, -glm::dot(centre, a) / h); };
    return {axis(right, half.x), axis(up, half.y), axis(toView, half.z)};
}

// Frame f of n from `elevation` (shaders/shared/impostor_frame.h): a colour ring's
// or the sun's. At elevation 0 it is as wide and deep as the box's
// horizontal radius and as tall as the box.
gpu::ImpostorBakePush frameView(const glm::vec4& quad, uint32_t f, uint32_t frames, float elevation) {
    const float a = gpu::impostorFrameAzimuth(f, frames);
    const float sinE = std::sin(elevation), cosE = std::cos(elevation);
    return bakeView(gpu::impostorFrameCentre(quad), gpu::impostorFrameRight(a), gpu::impostorFrameUp(a, sinE, cosE),
                    gpu::impostorFrameToView(a, sinE, cosE), gpu::impostorFrameHalfExtents(quad, sinE, cosE));
}

// A model's LOD0 mesh seen from `view`, each class culled as `cull` says.
void drawBakeFrame(VkCommandBuffer cmd, const BakePipeline& bake, const PlantModelInfo& model,
                   const gpu::ImpostorBakePush& view, const VkCullModeFlags (&cull)[kMeshClassCount]) {
    vkCmdPushConstants(cmd, bake.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(view), &view);
    for (uint32_t c = 0; c < kMeshClassCount; ++c) {
        const MeshRange& mesh = model.meshes[LOD_FULL][c];
        if (mesh.indexCount == 0) continue;
        vkCmdSetCullMode(cmd, cull[c]);
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, mesh.firstIndex, int32_t(mesh.vertexOffset), 0);
    }
}

// A supersampled target and the atlas image its frames are filtered into.
struct BakeDownsample {
    const BakeTarget* target;
    const Image* image;
};

// Filters the first `frames` layers of each target (`size`²), just drawn,
// down into mip 0 of the layers from `firstLayer` on of its image, which
// is in TRANSFER_DST_OPTIMAL (halvingBlit: a box filter, which averages as
// an MSAA resolve would, the sRGB colour in linear space).
void downsampleBakeRing(VkCommandBuffer cmd, std::initializer_list<BakeDownsample> targets, uint32_t size,
                        uint32_t firstLayer, uint32_t frames) {
    static_assert(kBakeSupersampling == 2, "a linear blit is a box filter only when it halves the side");
    // The frames' attachment writes must land before the blit reads them.
    const ImageTransition toSource{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                   VK_PIPELINE_STAGE_2_BLIT_BIT,
                                   VK_ACCESS_2_TRANSFER_READ_BIT,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    std::vector<VkImageMemoryBarrier2> barriers;
    for (const BakeDownsample& d : targets) barriers.push_back(atlasBarrier(d.target->image, 0, 1, frames, toSource));
    pipelineBarrier(cmd, barriers);
    const VkImageBlit blit = halvingBlit(size, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, frames},
                                         {VK_IMAGE_ASPECT_COLOR_BIT, 0, firstLayer, frames});
    for (const BakeDownsample& d : targets)
        vkCmdBlitImage(cmd, d.target->image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d.image->image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
}

// Every model from every direction into mip 0 of its layers: the colour
// frames of every ring, then the shadow frames.
void recordBakeFrames(VkCommandBuffer cmd, const ImpostorAtlas& atlas, const BakeTargets& targets,
                      const BakePipeline& bake, const PlantModelPool& pool, const Buffer& indices, float sunElevation) {
    // Level 0 of every layer receives one frame's filtered target; its old
    // contents are discarded.
    const ImageTransition toDestination{VK_PIPELINE_STAGE_2_NONE,     VK_ACCESS_2_NONE,
                                        VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                        VK_IMAGE_LAYOUT_UNDEFINED,    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    pipelineBarrier(cmd, {atlasBarrier(atlas.color, 0, 1, atlas.layers, toDestination),
                          atlasBarrier(atlas.normalDepth, 0, 1, atlas.layers, toDestination),
                          atlasBarrier(atlas.shadow, 0, 1, atlas.shadowLayers, toDestination)});

    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bake.layout, 0, 1, &bake.set, 0, nullptr);
    vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    const uint32_t frames = atlas.settings.frames;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bake.pipeline);
    for (const PlantModelInfo& model : pool.models) {
        for (uint32_t ring = 0; ring < IMPOSTOR_RINGS; ++ring) {
            prepareBakeRing(cmd, {&targets.color, &targets.normalDepth}, targets.depth, frames);
            for (uint32_t f = 0; f < frames; ++f) {
                beginBakeFrame(cmd, {&targets.color, &targets.normalDepth}, targets.depth, targets.size, f);
                drawBakeFrame(cmd, bake, model,
                              frameView(model.gpu.impostorQuad, f, frames, gpu::impostorRingElevation(ring)),
                              {VK_CULL_MODE_BACK_BIT, VK_CULL_MODE_NONE});
                vkCmdEndRendering(cmd);
            }
            downsampleBakeRing(cmd, {{&targets.color, &atlas.color}, {&targets.normalDepth, &atlas.normalDepth}},
                               targets.size, model.gpu.impostor.x + ring * frames, frames);
        }
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bake.shadowPipeline);
    for (const PlantModelInfo& model : pool.models) {
        prepareBakeRing(cmd, {&targets.shadow}, targets.shadowDepth, frames);
        for (uint32_t f = 0; f < frames; ++f) {
            beginBakeFrame(cmd, {&targets.shadow}, targets.shadowDepth, targets.shadowSize, f);
            drawBakeFrame(cmd, bake, model, frameView(model.gpu.impostorQuad, f, frames, sunElevation),
                          {VK_CULL_MODE_NONE, VK_CULL_MODE_NONE});
            vkCmdEndRendering(cmd);
        }
        downsampleBakeRing(cmd, {{&targets.shadow, &atlas.shadow}}, targets.shadowSize, model.gpu.impostor.w, frames);
    }
}

// Mips of `images` (size² at level 0, `mips` levels, `layers` layers): level
// k is blitted from level k-1 (premultiplied values and coverage average
// correctly); then every level is left for the billboards' fragment shaders.
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

// Reads the coverage of every layer back at mip kOutlineMip (or the last)
// and makes each layer's outline. The atlas is sampled before and after.
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

} // namespace

ImpostorAtlas bakeImpostorAtlas(GpuResources& owner, PlantModelPool& pool, const Buffer& vertices,
                                const Buffer& indices, float sunElevation, const ImpostorSettings& settings) {
    const GpuContext& ctx = owner.ctx();
    ImpostorAtlas atlas = createAtlas(owner, settings, atlasLayers(ctx, pool, settings));
    assignImpostorLayers(pool, settings);
    {
        GpuResources scratch(ctx); // the targets and pipeline only the bake uses
        const BakeTargets targets = createBakeTargets(scratch, settings);
        const BakePipeline bake = createBakePipeline(scratch, vertices);
        // All models and frames in one submission.
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            recordBakeFrames(cmd, atlas, targets, bake, pool, indices, sunElevation);
            recordMipChain(cmd, {&atlas.color, &atlas.normalDepth}, settings.frameSize, atlas.mipLevels, atlas.layers);
            recordMipChain(cmd, {&atlas.shadow}, settings.shadowFrameSize, atlas.shadowMipLevels, atlas.shadowLayers);
        });
    }
    atlas.outlines = readOutlines(ctx, atlas);
    return atlas;
}

} // namespace pf
