// The cluster pass (engine/field/cluster_pass.h) against its CPU reference
// on synthetic quadtrees: the same far nodes and near leaves, a cut that
// covers every leaf in view exactly once, near chunks that hold exactly the
// near leaves' plants, and the per-plant cull over them equal to cullOnCpu
// over the same leaves, a leaf turning near restarting settled.
#include "cull_fixture.h"

#include "engine/scene/clusters.h"
#include "shaders/shared/cluster_select.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>

namespace pf::test {
namespace {

const ClusterSquare kRoot{glm::vec2(-320.0f), 640.0f};
constexpr float kLeafSide = 20.0f;

// randomInstances in cluster order.
std::vector<gpu::FieldInstance> clusteredInstances(uint32_t n, uint32_t seed) {
    std::vector<gpu::FieldInstance> inst = randomInstances(n, seed, [](const gpu::FieldInstance&) { return true; });
    auto key = [](const gpu::FieldInstance& i) {
        return clusterOrderKey(kRoot, {i.positionScale.x, i.positionScale.z});
    };
    std::stable_sort(inst.begin(), inst.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
    return inst;
}

struct Readback {
    std::vector<uint32_t> far;      // sorted
    std::vector<glm::uvec2> chunks; // as written
    std::array<uint32_t, CLUSTER_STAT_COUNT> stats{};
    gpu::DrawCommand farDraw{};
    std::array<uint32_t, 3> dispatch{};
};

class ClusterPassTest : public CullPassTest {
protected:
    void build(uint32_t n, uint32_t seed) {
        f = layOut(clusteredInstances(n, seed), makeModels());
        tree = buildClusterTree(f.instances, f.models, kRoot, kLeafSide);
        nodes = createDeviceBufferWithData(resources, tree.nodes.data(), tree.nodes.size() * sizeof(gpu::ClusterNode),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        gpu::DrawCommand mesh{};
        mesh.indexCount = 99;
        cut = createClusterPass(resources, tree, nodes, mesh);
        create(f, CullKind::Camera, &cut.near);
        clusters = &cut;
        clusterHost = createHostBuffer(resources, cut.far.size + cut.near.size + cut.farDraw.size,
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    }

    Readback readCut() {
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy far{0, 0, cut.far.size}, near{0, cut.far.size, cut.near.size},
                draw{0, cut.far.size + cut.near.size, cut.farDraw.size};
            vkCmdCopyBuffer(cmd, cut.far.buffer, clusterHost.buffer, 1, &far);
            vkCmdCopyBuffer(cmd, cut.near.buffer, clusterHost.buffer, 1, &near);
            vkCmdCopyBuffer(cmd, cut.farDraw.buffer, clusterHost.buffer, 1, &draw);
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        Readback r;
        const auto* words = static_cast<const uint32_t*>(clusterHost.mapped);
        std::memcpy(&r.farDraw, words + cut.far.size / 4 + cut.near.size / 4, sizeof(r.farDraw));
        r.far.assign(words, words + r.farDraw.instanceCount);
        std::sort(r.far.begin(), r.far.end());
        const uint32_t* near = words + cut.far.size / 4;
        std::copy(near + 1, near + 4, r.dispatch.begin());
        for (uint32_t c = 0; c < near[0]; ++c) r.chunks.push_back({near[4 + 2 * c], near[5 + 2 * c]});
        r.stats = readClusterStats(cut);
        return r;
    }

    gpu::ClusterUniforms clusterUniforms(const gpu::CullUniforms& cull, uint32_t mode, float threshold) const {
        std::array<glm::vec4, 6> planes;
        std::copy(std::begin(cull.frustum), std::end(cull.frustum), planes.begin());
        gpu::ClusterUniforms u = makeClusterUniforms(planes, cull.camera, mode, threshold, cull.counts.w == 1u);
        u.counts.x = uint32_t(tree.nodes.size());
        u.counts.y = tree.leafCount();
        return u;
    }

    // The leaf whose range starts at or before plant i.
    uint32_t leafOf(uint32_t i) const {
        uint32_t lo = 0, hi = tree.leafCount();
        while (hi - lo > 1) {
            const uint32_t mid = (lo + hi) / 2;
            (tree.nodes[mid].range.x <= i ? lo : hi) = mid;
        }
        return lo;
    }

    // Near leaves from the chunks, each chunk checked to lie in its leaf and
    // each leaf's chunks to hold all its plants once.
    std::vector<uint32_t> nearLeaves(const Readback& r, std::map<uint32_t, bool>* restart = nullptr) const {
        std::map<uint32_t, uint32_t> plants;
        for (const glm::uvec2& chunk : r.chunks) {
            const uint32_t count = chunk.y & NEAR_CHUNK_COUNT_MASK, leaf = leafOf(chunk.x);
            EXPECT_GT(count, 0u);
            EXPECT_LE(count, uint32_t(CULL_GROUP_SIZE));
            EXPECT_LE(chunk.x + count, tree.nodes[leaf].range.x + tree.nodes[leaf].range.y);
            plants[leaf] += count;
            if (restart) (*restart)[leaf] = (chunk.y & NEAR_CHUNK_RESTART_BIT) != 0;
        }
        std::vector<uint32_t> leaves;
        for (const auto& [leaf, count] : plants) {
            EXPECT_EQ(count, tree.nodes[leaf].range.y) << "leaf " << leaf;
            leaves.push_back(leaf);
        }
        return leaves;
    }

    Field f;
    ClusterTree tree;
    Buffer nodes, clusterHost;
    ClusterPass cut;
};

const View kViews[] = {
    {{0, 30, -330}, {0, 0, 0}},  // over the whole field
    {{10, 2, 5}, {200, 0, 90}},  // in it, looking along the ground
    {{-50, 400, 0}, {0, 0, 1}},  // high above, looking down
    {{600, 50, 600}, {0, 0, 0}}, // from afar
};

TEST_F(ClusterPassTest, CutEqualsCpuAndCoversEveryLeafInViewOnce) {
    build(20000, 3);
    ASSERT_GT(tree.levels(), 3u);
    struct Case {
        uint32_t mode;
        float threshold;
    };
    for (const Case c : {Case{CLUSTER_CUT_AUTO, 2.0f}, Case{CLUSTER_CUT_AUTO, 0.5f}, Case{CLUSTER_CUT_AUTO, 8.0f},
                         Case{CLUSTER_CUT_ALL_FAR, 0.0f}, Case{CLUSTER_CUT_ALL_NEAR, 0.0f}})
        for (const View& v : kViews) {
            const gpu::CullUniforms cull =
                makeCullUniforms(viewProj(v), v.position, kFovY, kViewportHeight, 0.0f, true);
            const gpu::ClusterUniforms u = clusterUniforms(cull, c.mode, c.threshold);
            setClusterUniforms(cut, u);
            run(cull);
            const Readback r = readCut();
            const CpuClusterCut cpu = clusterCutOnCpu(tree.nodes, tree.leafCount(), u);
            EXPECT_EQ(r.far, cpu.far);
            EXPECT_EQ(nearLeaves(r), cpu.near);
            EXPECT_EQ(r.farDraw.indexCount, 99u);
            EXPECT_EQ(r.stats[CLUSTER_STAT_FAR], cpu.far.size());
            EXPECT_EQ(r.stats[CLUSTER_STAT_NEAR_LEAVES], cpu.near.size());
            EXPECT_GE(uint64_t(r.dispatch[0]) * r.dispatch[1], r.chunks.size()) << "a workgroup for every chunk";
            if (c.mode == CLUSTER_CUT_ALL_FAR) {
                EXPECT_TRUE(cpu.near.empty());
            }
            if (c.mode == CLUSTER_CUT_ALL_NEAR) {
                EXPECT_TRUE(cpu.far.empty());
            }
            const bool mixed = c.mode == CLUSTER_CUT_AUTO && !cpu.far.empty() && !cpu.near.empty();
            if (&v == &kViews[0] && c.threshold == 2.0f) {
                EXPECT_TRUE(mixed) << "the first view has both kinds";
            }

            for (uint32_t leaf = 0; leaf < tree.leafCount(); ++leaf) {
                uint32_t covered = cpu.decisions[leaf] == CLUSTER_NEAR ? 1u : 0u;
                for (uint32_t n = leaf; n != CLUSTER_NONE; n = tree.nodes[n].range.z)
                    covered += cpu.decisions[n] == CLUSTER_FAR ? 1u : 0u;
                if (gpu::clusterInFrustum(tree.nodes[leaf], u))
                    EXPECT_EQ(covered, 1u) << "leaf " << leaf << " mode " << c.mode;
                else
                    EXPECT_LE(covered, 1u);
            }
        }
}

TEST_F(ClusterPassTest, CullOverNearLeavesEqualsCpuAndRestartsLeavesTurningNear) {
    build(20000, 5);
    std::vector<uint32_t> cpuState;
    std::vector<bool> wasNear(tree.leafCount(), false);
    // The camera walks in, so leaves turn from far to near between frames.
    for (uint32_t frame = 0; frame < 6; ++frame) {
        const View v{{-250.0f + 60.0f * float(frame), 6.0f, -250.0f + 50.0f * float(frame)}, {0, 0, 0}};
        const gpu::CullUniforms cull =
            makeCullUniforms(viewProj(v), v.position, kFovY, kViewportHeight, 0.05f, frame == 0);
        const gpu::ClusterUniforms u = clusterUniforms(cull, CLUSTER_CUT_AUTO, 3.0f);
        setClusterUniforms(cut, u);
        const GpuFrame gpuFrame = run(cull);
        std::map<uint32_t, bool> restart;
        const std::vector<uint32_t> leaves = nearLeaves(readCut(), &restart);
        const CpuClusterCut cpu = clusterCutOnCpu(tree.nodes, tree.leafCount(), u);
        ASSERT_EQ(leaves, cpu.near);
        std::vector<CpuNearRange> near;
        bool anyRestart = false;
        for (uint32_t leaf : cpu.near) {
            const bool restarts = frame == 0 || !wasNear[leaf];
            EXPECT_EQ(restart[leaf], restarts) << "leaf " << leaf << " frame " << frame;
            anyRestart |= frame > 0 && restarts;
            near.push_back({tree.nodes[leaf].range.x, tree.nodes[leaf].range.y, restarts});
        }
        for (uint32_t leaf = 0; leaf < tree.leafCount(); ++leaf) wasNear[leaf] = cpu.decisions[leaf] == CLUSTER_NEAR;
        if (frame == 3) {
            EXPECT_TRUE(anyRestart) << "some leaf turned near";
        }
        const CpuCullResult expected = cullOnCpu(f.instances, f.models, cull, cpuState, near);
        ASSERT_EQ(gpuFrame.lists.size(), expected.lists.size());
        for (size_t l = 0; l < expected.lists.size(); ++l) EXPECT_EQ(gpuFrame.lists[l], expected.lists[l]) << l;
        for (const CpuNearRange& range : near)
            for (uint32_t i = range.first; i < range.first + range.count; ++i)
                ASSERT_EQ(gpuFrame.state[i], cpuState[i]) << "plant " << i << " frame " << frame;
    }
}

} // namespace
} // namespace pf::test
