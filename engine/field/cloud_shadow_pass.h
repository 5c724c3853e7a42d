// The clouds' shadows on the ground (docs/CLOUDS.md), for the clouds whose
// `shadow` is set: the map of engine/scene/cloud_shadow.h in a texel
// buffer, and the terrain's chunks of the frame drawn again over
// themselves after the sky, depth-tested against what is drawn (pulled a
// little towards the camera, so the terrain's own depth passes and plants
// in front do not), multiplying the ground's colour by the shade
// (shaders/cloud_shadow.vert, .frag). Plants are not shaded by it.
#pragma once

#include "engine/scene/cloud_shadow.h"
#include "engine/scene/terrain_chunks.h"
#include "engine/vk/resources.h"

namespace pf {

struct CloudShadowPass {
    CloudShadowMap map; // width 0: no cloud casts a shadow and nothing is recorded
    Buffer transmittance;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Owned by `owner`. `frameUniforms` begins with FrameUniforms; `terrainVertices`
// holds the drawn terrain's TerrainVertex[] (field_layouts.h); `sun` is the
// unit vector toward the scene's sun.
CloudShadowPass createCloudShadowPass(GpuResources& owner, const std::vector<Cloud>& clouds, const glm::vec3& sun,
                                      const Buffer& frameUniforms, const Buffer& terrainVertices,
                                      VkSampleCountFlagBits samples);

// Inside the colour pass's rendering, after the terrain: the chunks of
// `ranges` from `terrainIndices`, the map moved by `drift` (metres, the
// clouds' wind drift at the frame's time). Rebinds set 0.
void recordCloudShadowPass(VkCommandBuffer cmd, const CloudShadowPass& pass, const Buffer& terrainIndices,
                           const TerrainRanges& ranges, const glm::vec3& drift);

} // namespace pf
