#include "engine/vk/compute_set.h"

namespace pf {

ComputeSet createComputeSet(GpuResources& owner, DescriptorTable table, uint32_t pushConstantBytes,
                            std::span<const VkDescriptorSetLayout> laterSets) {
    ComputeSet set;
    set.setLayout = createSetLayout(owner, table);
    std::vector<VkDescriptorSetLayout> layouts = {set.setLayout};
    layouts.insert(layouts.end(), laterSets.begin(), laterSets.end());
    set.pipelineLayout = createPipelineLayout(owner, layouts, {VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes});
    set.descriptorSet = createSet(owner, set.setLayout, table);
    return set;
}

void bindComputeSet(VkCommandBuffer cmd, const ComputeSet& set) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set.pipelineLayout, 0, 1, &set.descriptorSet, 0,
                            nullptr);
}

} // namespace pf
