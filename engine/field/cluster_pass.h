// The cluster pass (docs/CLUSTERS.md): per frame, one compute invocation per
// node of the field's quadtree (engine/scene/clusters.h) picks the cut
// through it (shaders/shared/cluster_select.h): far nodes go to the canopy's
// instanced draw, near leaves into chunks of plants that the per-plant cull
// (engine/field/cull_pass.h) dispatches over indirectly. The sun's casters
// use the same pass with CLUSTER_CUT_BOX_ONLY: the leaves meeting its box.
#pragma once

#include "engine/field/cluster_cut.h"
#include "engine/scene/clusters.h"
#include "engine/vk/compute_set.h"
#include "engine/vk/resources.h"
#include "shaders/shared/cluster_layouts.h"

#include <glm/glm.hpp>

#include <array>
#include <span>
#include <vector>

namespace pf {

struct ClusterPass {
    ComputeSet set; // CLUSTER_BINDING_*
    VkPipeline clusterPipeline = VK_NULL_HANDLE;
    VkPipeline dispatchPipeline = VK_NULL_HANDLE;

    Buffer uniforms;  // host-visible ClusterUniforms
    Buffer leafState; // uint per leaf: near last frame
    Buffer near;      // header (count, VkDispatchIndirectCommand), then uvec2 chunks (CullPassInputs::near)
    Buffer far;       // uint far node indices (the canopy's instances)
    Buffer farDraw;   // DrawCommand of the canopy: its mesh, instanceCount = far nodes
    Buffer stats;     // uint[CLUSTER_STAT_COUNT]
    Buffer readback;  // host-visible copy of stats

    uint32_t nodeCount = 0;
    uint32_t leafCount = 0;
    uint32_t maxGroupsPerRow = 0; // maxComputeWorkGroupCount[0]: the near dispatch's rows
    gpu::DrawCommand farMesh{};   // the canopy's indexed mesh, instanceCount 0
};

// `nodes` a storage buffer of tree.nodes; `farMesh` the canopy draw without
// instances. What the pass creates is owned by `owner`.
ClusterPass createClusterPass(GpuResources& owner, const ClusterTree& tree, const Buffer& nodes,
                              const gpu::DrawCommand& farMesh);

// Per frame, before record: the uniforms (makeClusterUniforms,
// cluster_cut.h) with the counts and limits filled from the pass.
void setClusterUniforms(const ClusterPass& pass, gpu::ClusterUniforms uniforms);

// Clears the lists, picks the cut, writes the cull's indirect dispatch, and
// the barriers that make the chunks readable by the cull and the far list
// and draw by the canopy's draw.
void recordClusterPass(VkCommandBuffer cmd, const ClusterPass& pass);

// The canopy of the far nodes: one indexed draw of ClusterPass::farDraw.
// The caller binds the pipeline, the mesh's index buffer and the draw set.
void drawCanopyIndirect(VkCommandBuffer cmd, const GpuContext& ctx, const ClusterPass& pass);

// The counters of the last recorded frame (after its fence), CLUSTER_STAT_*.
std::array<uint32_t, CLUSTER_STAT_COUNT> readClusterStats(const ClusterPass& pass);

} // namespace pf
