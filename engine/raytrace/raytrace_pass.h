// A packed InstanceGraph (engine/raytrace/gpu_graph.h) on the device, and
// the compute pass that traces a buffer of rays through it
// (shaders/raytrace_rays.comp, docs/RAYTRACING.md "The GPU traversal").
#pragma once

#include "engine/raytrace/gpu_graph.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/resources.h"

#include <span>
#include <vector>

namespace pf {

// Uint views of device-local copies of the packed arrays, bound at
// RAYTRACE_BINDING_NODES to RAYTRACE_BINDING_TRIANGLES as uniform texel
// buffers.
struct GpuGraphBuffers {
    VkBufferView nodes = VK_NULL_HANDLE;
    VkBufferView items = VK_NULL_HANDLE;
    VkBufferView objectRoots = VK_NULL_HANDLE;
    VkBufferView instances = VK_NULL_HANDLE;
    VkBufferView primitives = VK_NULL_HANDLE;
    VkBufferView triangles = VK_NULL_HANDLE;
    uint32_t rootNode = RAYTRACE_NO_NODE;
};

// Owned by `owner`; throws when an array holds more texels than the
// device's maxTexelBufferElements.
GpuGraphBuffers uploadGraph(GpuResources& owner, const GpuGraph& graph);

// The graph's entries of a descriptor table, for a pass whose shader
// includes raytrace_traverse.glsl.
std::vector<DescriptorBinding> graphBindings(const GpuGraphBuffers& graph, VkShaderStageFlags stages);

struct RaytracePass {
    ComputeSet set; // the graph's buffers, rays and hits; RtTracePush
    VkPipeline pipeline = VK_NULL_HANDLE;
    Buffer rays; // host-visible RtRay[capacity]
    Buffer hits; // host-visible RtHit[capacity]
    uint32_t capacity = 0;
    uint32_t rootNode = RAYTRACE_NO_NODE;
};

// Room for `capacity` rays a dispatch; owned by `owner`.
RaytracePass createRaytracePass(GpuResources& owner, const GpuGraphBuffers& graph, uint32_t capacity);

// Records the trace of the first `rayCount` rays of pass.rays into
// pass.hits, readable by the host afterwards.
void recordRaytrace(VkCommandBuffer cmd, const RaytracePass& pass, uint32_t rayCount, lsys::HitQuery query);

// Writes the rays (at most pass.capacity, else std::invalid_argument),
// traces them, waits and returns their hits.
std::vector<gpu::RtHit> traceRays(const GpuContext& ctx, const RaytracePass& pass, std::span<const gpu::RtRay> rays,
                                  lsys::HitQuery query);

} // namespace pf
