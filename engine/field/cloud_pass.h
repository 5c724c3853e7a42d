// The clouds of a scene (docs/CLOUDS.md): one camera-facing quad per sphere
// (shaders/cloud.vert, cloud.frag), drawn inside the colour pass after the
// opaque geometry and the sky, before the anti-aliasing: premultiplied
// alpha, blended back to front, depth-tested against the scene without
// writing depth. The CPU sorts the spheres every frame (cloud_billboards.h)
// into a host-visible buffer, so a frame depends only on its time and view.
#pragma once

#include "engine/scene/scene.h"
#include "engine/vk/resources.h"

#include <cstdint>

namespace pf {

struct CloudPass {
    uint32_t spheres = 0; // 0: the scene has no clouds and nothing is recorded
    Buffer billboards;    // CloudBillboard[spheres], host-visible, written by setCloudView
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Owned by `owner`. `frameUniforms` begins with the FrameUniforms block
// (shaders/shared/layouts.h); the pipeline draws into the colour pass's attachments
// with `samples` samples. Without clouds only `spheres` (0) is set.
CloudPass createCloudPass(GpuResources& owner, const std::vector<Cloud>& clouds, const Buffer& frameUniforms,
                          VkSampleCountFlagBits samples);

// The billboards of the frame at scene time `time` seen from `camera`
// looking along `forward` (unit). Call only while no frame is in flight.
void setCloudView(const CloudPass& pass, const Scene& scene, float time, const glm::vec3& camera,
                  const glm::vec3& forward);

// Inside the colour pass's rendering; rebinds set 0, so a caller drawing
// after it binds its own again.
void recordCloudPass(VkCommandBuffer cmd, const CloudPass& pass);

} // namespace pf
