#include "engine/field/cluster_cut.h"

#include "shaders/shared/cluster_select.h"

#include <algorithm>

namespace pf {

gpu::ClusterUniforms makeClusterUniforms(const std::array<glm::vec4, 6>& planes, const glm::vec4& camera, uint32_t cut,
                                         float thresholdPixels, bool firstFrame) {
    gpu::ClusterUniforms u{};
    std::copy(planes.begin(), planes.end(), u.frustum);
    u.camera = camera;
    u.counts = glm::uvec4(0, 0, cut, firstFrame ? 1u : 0u);
    u.threshold = glm::vec4(thresholdPixels, 0, 0, 0);
    return u;
}

bool canopyCanBeDrawn(std::span<const gpu::ClusterNode> nodes, const glm::vec4& camera, uint32_t cut,
                      float thresholdPixels) {
    const gpu::ClusterNode& root = nodes.back();
    const glm::vec3 eye(camera);
    const glm::vec3 farthest = glm::max(glm::abs(eye - glm::vec3(root.boxMin)), glm::abs(eye - glm::vec3(root.boxMax)));
    const float leafPixels = gpu::pixelsAtDistance(0.5f * nodes[0].square.w, camera.w, glm::length(farthest));
    return cut == CLUSTER_CUT_ALL_FAR || (cut == CLUSTER_CUT_AUTO && leafPixels < thresholdPixels);
}

CpuClusterCut clusterCutOnCpu(std::span<const gpu::ClusterNode> nodes, uint32_t leafCount,
                              const gpu::ClusterUniforms& uniforms) {
    CpuClusterCut cut;
    for (uint32_t n = 0; n < nodes.size(); ++n) {
        const gpu::ClusterNode& node = nodes[n];
        const uint32_t parent = node.range.z;
        const float parentPixels = parent == CLUSTER_NONE ? CLUSTER_ROOT_PARENT_PIXELS
                                                          : gpu::clusterCellPixels(nodes[parent], uniforms.camera);
        const uint32_t decision = gpu::clusterDecision(node, gpu::clusterCellPixels(node, uniforms.camera),
                                                       parentPixels, gpu::clusterInFrustum(node, uniforms), uniforms);
        cut.decisions.push_back(decision);
        if (decision == CLUSTER_FAR) cut.far.push_back(n);
        if (decision == CLUSTER_NEAR && n < leafCount) cut.near.push_back(n);
    }
    return cut;
}

} // namespace pf
