#include "engine/raytrace/raytrace_pass.h"

#include "engine/vk/pipeline.h"

#include "shaders/raytrace_rays_comp.spv.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace pf {
namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// A device-local copy of the array and its view of `format` texels.
template <class T>
VkBufferView uploadArray(GpuResources& owner, const std::vector<T>& array, VkFormat format) {
    const Buffer buffer = createDeviceBufferWithData(owner, array.data(), array.size() * sizeof(T),
                                                     VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    return createTexelView(owner, buffer, format);
}

} // namespace

GpuGraphBuffers uploadGraph(GpuResources& owner, const GpuGraph& graph) {
    constexpr VkFormat kRecords = VK_FORMAT_R32G32B32A32_UINT, kWords = VK_FORMAT_R32_UINT;
    return {uploadArray(owner, graph.nodes, kRecords),
            uploadArray(owner, graph.items, kWords),
            uploadArray(owner, graph.objectRoots, kWords),
            uploadArray(owner, graph.instances, kRecords),
            uploadArray(owner, graph.primitives, kRecords),
            uploadArray(owner, graph.triangles, kRecords),
            graph.rootNode};
}

std::vector<DescriptorBinding> graphBindings(const GpuGraphBuffers& graph, VkShaderStageFlags stages) {
    return {texelBuffer(RAYTRACE_BINDING_NODES, stages, graph.nodes),
            texelBuffer(RAYTRACE_BINDING_ITEMS, stages, graph.items),
            texelBuffer(RAYTRACE_BINDING_OBJECT_ROOTS, stages, graph.objectRoots),
            texelBuffer(RAYTRACE_BINDING_INSTANCES, stages, graph.instances),
            texelBuffer(RAYTRACE_BINDING_PRIMITIVES, stages, graph.primitives),
            texelBuffer(RAYTRACE_BINDING_TRIANGLES, stages, graph.triangles)};
}

RaytracePass createRaytracePass(GpuResources& owner, const GpuGraphBuffers& graph, uint32_t capacity) {
    RaytracePass pass;
    pass.capacity = capacity;
    pass.rootNode = graph.rootNode;
    pass.rays = createHostBuffer(owner, std::max<VkDeviceSize>(capacity, 1) * sizeof(gpu::RtRay),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pass.hits = createHostBuffer(owner, std::max<VkDeviceSize>(capacity, 1) * sizeof(gpu::RtHit),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::vector<DescriptorBinding> table = graphBindings(graph, kCompute);
    table.push_back(storageBuffer(RAYTRACE_BINDING_RAYS, kCompute, pass.rays));
    table.push_back(storageBuffer(RAYTRACE_BINDING_HITS, kCompute, pass.hits));
    pass.set = createComputeSet(owner, table, sizeof(gpu::RtTracePush));
    pass.pipeline = createComputePipeline(owner, pass.set.pipelineLayout, spirv_raytrace_rays_comp);
    return pass;
}

void recordRaytrace(VkCommandBuffer cmd, const RaytracePass& pass, uint32_t rayCount, lsys::HitQuery query) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline);
    bindComputeSet(cmd, pass.set);
    const gpu::RtTracePush push{rayCount, uint32_t(query), pass.rootNode, 0};
    vkCmdPushConstants(cmd, pass.set.pipelineLayout, kCompute, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, (rayCount + RAYTRACE_GROUP_SIZE - 1) / RAYTRACE_GROUP_SIZE, 1, 1);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

std::vector<gpu::RtHit> traceRays(const GpuContext& ctx, const RaytracePass& pass, std::span<const gpu::RtRay> rays,
                                  lsys::HitQuery query) {
    if (rays.size() > pass.capacity)
        throw std::invalid_argument(std::to_string(rays.size()) + " rays are more than the pass holds (" +
                                    std::to_string(pass.capacity) + ")");
    std::memcpy(pass.rays.mapped, rays.data(), rays.size_bytes());
    submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordRaytrace(cmd, pass, uint32_t(rays.size()), query); });
    const auto* hits = static_cast<const gpu::RtHit*>(pass.hits.mapped);
    return {hits, hits + rays.size()};
}

} // namespace pf
