#include "engine/scene_renderer.h"

#include "engine/meshes.h"
#include "engine/pipeline.h"
#include "engine/vk_check.h"

#include <cstdint>
#include <cstring>

#include "shaders/ground_frag.spv.h"
#include "shaders/ground_vert.spv.h"
#include "shaders/segment_frag.spv.h"
#include "shaders/segment_vert.spv.h"
#include "shaders/sky_frag.spv.h"
#include "shaders/sky_vert.spv.h"

namespace pf {
namespace {

constexpr uint32_t kCylinderSides = 12;

} // namespace

SceneRenderer::SceneRenderer(const GpuContext& ctx, const SceneGeometry& geometry, VkSampleCountFlagBits samples)
    : ctx_(ctx), samples_(samples) {
    uniforms_ = createHostBuffer(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

    // A zero-sized buffer is invalid, so an empty scene keeps one unused record.
    segmentCount_ = uint32_t(geometry.segments.size());
    std::vector<gpu::SegmentInstance> segments = geometry.segments;
    if (segments.empty()) segments.push_back({});
    segments_ = createDeviceBufferWithData(ctx, segments.data(), segments.size() * sizeof(segments[0]),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    const MeshData cylinder = makeCylinderMesh(kCylinderSides);
    cylinderIndexCount_ = uint32_t(cylinder.indices.size());
    cylinderVertices_ = createDeviceBufferWithData(ctx, cylinder.vertices.data(),
                                                   cylinder.vertices.size() * sizeof(gpu::MeshVertex),
                                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cylinderIndices_ = createDeviceBufferWithData(ctx, cylinder.indices.data(),
                                                  cylinder.indices.size() * sizeof(uint32_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    createDescriptors();
    createPipelines();
}

SceneRenderer::~SceneRenderer() {
    VkDevice device = ctx_.device;
    vkDeviceWaitIdle(device);
    for (VkPipeline p : {skyPipeline_, groundPipeline_, segmentPipeline_}) vkDestroyPipeline(device, p, nullptr);
    vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
    vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    for (Buffer* b : {&uniforms_, &segments_, &cylinderVertices_, &cylinderIndices_}) destroyBuffer(ctx_, *b);
}

void SceneRenderer::createDescriptors() {
    const VkDescriptorSetLayoutBinding bindings[] = {
        {BINDING_FRAME_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {BINDING_SEGMENT_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {BINDING_MESH_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
    };
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = 3;
    layoutInfo.pBindings = bindings;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &layoutInfo, nullptr, &setLayout_));

    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 2;
    poolInfo.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(ctx_.device, &poolInfo, nullptr, &descriptorPool_));

    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = descriptorPool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &setLayout_;
    VK_CHECK(vkAllocateDescriptorSets(ctx_.device, &alloc, &descriptorSet_));

    const VkDescriptorBufferInfo infos[] = {{uniforms_.buffer, 0, VK_WHOLE_SIZE},
                                            {segments_.buffer, 0, VK_WHOLE_SIZE},
                                            {cylinderVertices_.buffer, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet writes[3];
    for (uint32_t i = 0; i < 3; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = descriptorSet_;
        writes[i].dstBinding = bindings[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = bindings[i].descriptorType;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(ctx_.device, 3, writes, 0, nullptr);

    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &setLayout_;
    VK_CHECK(vkCreatePipelineLayout(ctx_.device, &pipelineLayoutInfo, nullptr, &pipelineLayout_));
}

void SceneRenderer::createPipelines() {
    VkDevice device = ctx_.device;
    struct Stages {
        VkShaderModule vertex, fragment;
    };
    const Stages sky{createShaderModule(device, spirv_sky_vert), createShaderModule(device, spirv_sky_frag)};
    const Stages ground{createShaderModule(device, spirv_ground_vert), createShaderModule(device, spirv_ground_frag)};
    const Stages segment{createShaderModule(device, spirv_segment_vert),
                         createShaderModule(device, spirv_segment_frag)};

    GraphicsPipelineDesc desc;
    desc.layout = pipelineLayout_;
    desc.colorFormat = kColorFormat;
    desc.depthFormat = kDepthFormat;
    desc.samples = samples_;

    // The sky covers the screen behind everything, so it neither tests nor writes depth.
    desc.vertex = sky.vertex;
    desc.fragment = sky.fragment;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = desc.depthWrite = false;
    skyPipeline_ = createGraphicsPipeline(device, desc);

    desc.vertex = ground.vertex;
    desc.fragment = ground.fragment;
    desc.depthTest = desc.depthWrite = true;
    groundPipeline_ = createGraphicsPipeline(device, desc);

    desc.vertex = segment.vertex;
    desc.fragment = segment.fragment;
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    segmentPipeline_ = createGraphicsPipeline(device, desc);

    for (const Stages& s : {sky, ground, segment}) {
        vkDestroyShaderModule(device, s.vertex, nullptr);
        vkDestroyShaderModule(device, s.fragment, nullptr);
    }
}

void SceneRenderer::setFrameUniforms(const gpu::FrameUniforms& uniforms) {
    std::memcpy(uniforms_.mapped, &uniforms, sizeof(uniforms));
}

void SceneRenderer::record(VkCommandBuffer cmd, const RenderTarget& target) const {
    const bool msaa = target.samples != VK_SAMPLE_COUNT_1_BIT;
    const VkImage drawnColor = msaa ? target.msaaColor.image : target.color.image;

    // Previous contents are discarded (UNDEFINED): the colour image waits only
    // for the last frame's copy or blit out of it, depth for its last writes.
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    if (msaa)
        imageBarrier(cmd, drawnColor, VK_IMAGE_ASPECT_COLOR_BIT,
                     {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    const VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    imageBarrier(cmd, target.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                 {depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthStages,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});

    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = msaa ? target.msaaColor.view : target.color.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    if (msaa) {
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = target.color.view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = target.depth.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};

    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, target.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);

    // Negative height flips y so world and clip space stay y-up.
    const VkViewport viewport{0.0f, float(target.extent.height), float(target.extent.width),
                              -float(target.extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, target.extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &descriptorSet_, 0, nullptr);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, skyPipeline_);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundPipeline_);
    vkCmdDraw(cmd, 6, 1, 0, 0);
    if (segmentCount_ > 0) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, segmentPipeline_);
        vkCmdBindIndexBuffer(cmd, cylinderIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, cylinderIndexCount_, segmentCount_, 0, 0, 0);
    }
    vkCmdEndRendering(cmd);

    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
}

} // namespace pf
