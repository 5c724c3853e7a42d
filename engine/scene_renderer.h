// Records one frame — sky, lit ground, instanced plant segments — into a
// RenderTarget. The headless capture and the window both call record(), so
// the two paths draw exactly the same thing.
#pragma once

#include "engine/render_target.h"
#include "shaders/layouts.h"

#include <vector>

namespace pf {

struct SceneGeometry {
    std::vector<gpu::SegmentInstance> segments;
};

class SceneRenderer {
public:
    SceneRenderer(const GpuContext& ctx, const SceneGeometry& geometry, VkSampleCountFlagBits samples);
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // Host-visible uniforms: call only while no frame using them is in flight.
    void setFrameUniforms(const gpu::FrameUniforms& uniforms);
    // Leaves target.color in TRANSFER_SRC_OPTIMAL, ready for readback or blit.
    void record(VkCommandBuffer cmd, const RenderTarget& target) const;

    VkSampleCountFlagBits samples() const { return samples_; }
    uint32_t segmentCount() const { return segmentCount_; }

private:
    const GpuContext& ctx_;
    VkSampleCountFlagBits samples_;
    uint32_t segmentCount_ = 0;
    uint32_t cylinderIndexCount_ = 0;

    Buffer uniforms_;
    Buffer segments_;
    Buffer cylinderVertices_;
    Buffer cylinderIndices_;

    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline skyPipeline_ = VK_NULL_HANDLE;
    VkPipeline groundPipeline_ = VK_NULL_HANDLE;
    VkPipeline segmentPipeline_ = VK_NULL_HANDLE;

    void createDescriptors();
    void createPipelines();
};

} // namespace pf
