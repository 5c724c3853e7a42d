// The impostor bake (impostor_atlas.h): every model drawn from every frame
// direction into targets of twice the frame's side, a ring of frames at a
// time, each ring filtered down 2:1 into its atlas layers (2×2
// supersampling), then from every shadow frame direction into its
// coverage-only targets and the shadow frames' layers, the mip chains
// blitted, and the outlines read back.
#include "engine/field/impostor_atlas.h"

#include "engine/field/impostor_atlas_images.h"
#include "engine/field/impostor_sources.h"

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

constexpr VkFormat kBakeDepthFormat = VK_FORMAT_D32_SFLOAT;
// Frames are drawn at this many times the frame's side, one sample a pixel,
// and filtered down to it: 2×2 supersampling. On lavapipe it takes about two
// thirds of the time of 4× MSAA at the frame's side, whose per-sample coverage
// and resolve cost more than shading four times the pixels.
constexpr uint32_t kBakeSupersampling = 2;

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
                      const BakePipeline& bake, const PlantModelPool& pool, const std::vector<uint32_t>& sources,
                      const Buffer& indices, float sunElevation) {
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
    for (size_t m = 0; m < pool.models.size(); ++m) {
        if (sources[m] != m) continue; // it shows another variant's frames
        const PlantModelInfo& model = pool.models[m];
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
    for (size_t m = 0; m < pool.models.size(); ++m) {
        if (sources[m] != m) continue;
        const PlantModelInfo& model = pool.models[m];
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

} // namespace

ImpostorAtlas bakeImpostorAtlas(GpuResources& owner, PlantModelPool& pool, const Buffer& vertices,
                                const Buffer& indices, float sunElevation, const ImpostorSettings& settings) {
    const GpuContext& ctx = owner.ctx();
    const std::vector<uint32_t> sources = impostorSources(pool, impostorModelCapacity(ctx, settings));
    ImpostorAtlas atlas = createAtlas(owner, settings, atlasLayers(sources, settings));
    assignImpostorLayers(pool, settings, sources);
    {
        GpuResources scratch(ctx); // the targets and pipeline only the bake uses
        const BakeTargets targets = createBakeTargets(scratch, settings);
        const BakePipeline bake = createBakePipeline(scratch, vertices);
        // All models and frames in one submission.
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            recordBakeFrames(cmd, atlas, targets, bake, pool, sources, indices, sunElevation);
            recordMipChain(cmd, {&atlas.color, &atlas.normalDepth}, settings.frameSize, atlas.mipLevels, atlas.layers);
            recordMipChain(cmd, {&atlas.shadow}, settings.shadowFrameSize, atlas.shadowMipLevels, atlas.shadowLayers);
        });
    }
    atlas.outlines = readOutlines(ctx, atlas);
    return atlas;
}

} // namespace pf
