// The field's draw set (shaders/field_common.glsl, FIELD_BINDING_*): what
// every pass drawing the field's surfaces reads — the frame block, the
// plants, the vertex pool, the atlas, the shadow map, the terrain, the
// skeletons' poses, the clusters' canopy, the traced sun's visibility — in
// one table with one layout, and one set per visible list: the colour
// pass's sets bind the cull pass's lists or the naive list, each shadow
// map's set its caster pass's lists. The push constant says which pass
// draws (FieldPush).
#pragma once

#include "engine/field/cluster_pass.h"
#include "engine/field/field_clusters.h"
#include "engine/field/field_geometry.h"
#include "engine/field/raytraced_sun_pass.h"
#include "engine/field/shadow_map.h"
#include "engine/physics/field_motion.h"
#include "engine/vk/descriptors.h"

#include <span>
#include <vector>

namespace pf {

constexpr VkShaderStageFlags kDrawStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// What every set binds, all but its visible list.
struct DrawTableInputs {
    const Buffer* frame = nullptr; // FrameUniforms then FieldFrame (std140), host-visible
    const FieldGeometry* geometry = nullptr;
    const FieldPlantBuffers* plants = nullptr;
    const ShadowMap* shadow = nullptr;
    const FieldMotion* motion = nullptr;
    // With clusters: their nodes and canopy, and the camera's cut (its far
    // list). Null without: the canopy's bindings get one texel.
    const FieldClusters* clusters = nullptr;
    const ClusterPass* cameraClusters = nullptr;
    const RaytracedSunPass* raytracedSun = nullptr;
};

struct DrawTable {
    std::vector<DescriptorBinding> bindings; // FIELD_BINDING_VISIBLE without a view: each set binds its own
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE; // the set and the FieldPush constants
};

// Owned by `owner`.
DrawTable createDrawTable(GpuResources& owner, const DrawTableInputs& inputs);

// One set per visible list (uint entries, read through a texel view), in a
// pool of their own, owned by `owner`.
std::vector<VkDescriptorSet> createDrawSets(GpuResources& owner, const DrawTable& table,
                                            std::span<const Buffer* const> visibleLists);

// The traced sun's visibility written again into `sets` after its images
// were made for a new size (resizeTracedSunImages).
void writeRaytracedSunVisibility(const GpuContext& ctx, std::span<const VkDescriptorSet> sets,
                                 const RaytracedSunPass& raytracedSun);

void bindDrawSet(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set);
// FieldPush: which pass draws (FIELD_PASS_*) and which part of the impostor list (IMPOSTOR_PART_*).
void pushFieldPass(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t pass,
                   uint32_t impostorPart = IMPOSTOR_PART_NONE);

} // namespace pf
