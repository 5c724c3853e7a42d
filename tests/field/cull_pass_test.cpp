// The cull + LOD compute pass (engine/field/cull_pass.h) against its CPU reference
// cullOnCpu, on synthetic models and random fields; every GPU test runs with
// the validation layer on.
#include "cull_fixture.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/target_pass.h"
#include "engine/vk/vk_check.h"
#include "gpu_test.h"
#include "shaders/shared/layouts.h"
#include "shaders/shared/lod_select.h"
#include "shaders/sky_frag.spv.h"
#include "shaders/sky_vert.spv.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <set>

namespace pf::test {
namespace {

gpu::CullUniforms uniformsFor(const View& v, float dt, bool first, uint32_t forced = LOD_NOT_FORCED) {
    return makeCullUniforms(viewProj(v), v.position, kFovY, kViewportHeight, dt, first, forced);
}

// True when float rounding could flip a decision for this instance under
// these uniforms: the sphere within a hair of a plane, or its projected
// height within a hair of a LOD boundary.
bool ambiguous(const gpu::FieldInstance& inst, const gpu::PlantModel& model, const gpu::CullUniforms& u) {
    const ExactSphere s = exactSphere(inst, model);
    for (const glm::vec4& p : u.frustum)
        if (grazesPlane(s, p)) return true;
    const double pixels = 2.0 * s.radius * u.camera.w / std::max(glm::distance(glm::dvec3(u.camera), s.centre), 0.001);
    const double h = model.lod.z;
    for (double threshold : {double(model.lod.x), double(model.lod.y)})
        for (double boundary : {threshold, threshold * (1 - h), threshold * (1 + h)})
            if (nearBoundary(pixels, boundary)) return true;
    return false;
}

// n instances around the camera, none of them ambiguous under any of `frames`.
std::vector<gpu::FieldInstance> makeField(uint32_t n, uint32_t seed, const std::vector<gpu::PlantModel>& models,
                                          const std::vector<gpu::CullUniforms>& frames) {
    return randomInstances(n, seed, [&](const gpu::FieldInstance& inst) {
        return std::none_of(frames.begin(), frames.end(),
                            [&](const gpu::CullUniforms& u) { return ambiguous(inst, models[inst.ids.x], u); });
    });
}

Field randomField(uint32_t n, uint32_t seed) {
    std::vector<gpu::PlantModel> models = makeModels();
    std::vector<gpu::FieldInstance> instances =
        makeField(n, seed, models, {uniformsFor(kStart, 0, true), uniformsFor(kMoved, 0.1f, false)});
    return layOut(std::move(instances), std::move(models));
}

size_t entries(const std::vector<std::vector<uint32_t>>& lists) {
    size_t n = 0;
    for (const auto& l : lists) n += l.size();
    return n;
}

TEST(CullPlanes, FrustumPlanesBoundTheClipVolume) {
    const View v = kStart;
    const std::array<glm::vec4, 6> planes = frustumPlanes(viewProj(v));
    auto inside = [&](glm::vec3 p) {
        return std::all_of(planes.begin(), planes.end(),
                           [&](glm::vec4 pl) { return glm::dot(glm::vec3(pl), p) + pl.w >= 0; });
    };
    for (const glm::vec4& pl : planes) EXPECT_NEAR(glm::length(glm::vec3(pl)), 1.0f, 1e-5f);
    EXPECT_TRUE(inside({0.0f, 1.7f, 10.0f}));
    EXPECT_FALSE(inside({0.0f, 1.7f, -10.0f}));  // behind
    EXPECT_FALSE(inside({0.0f, 1.7f, 0.05f}));   // before the near plane (0.1)
    EXPECT_FALSE(inside({0.0f, 1.7f, 1001.0f})); // past the far plane
    EXPECT_FALSE(inside({30.0f, 1.7f, 10.0f}));  // left or right of a 16:9, 60° view
    EXPECT_FALSE(inside({0.0f, 20.0f, 10.0f}));  // above
    // The near plane passes 0.1 m in front of the camera.
    EXPECT_NEAR(glm::dot(glm::vec3(planes[4]), glm::vec3(0, 1.7f, 0.1f)) + planes[4].w, 0.0f, 1e-4f);
}

TEST(CullPlanes, PixelsPerMetreFollowsFov) {
    const gpu::CullUniforms u = uniformsFor(kStart, 0, true);
    EXPECT_NEAR(u.camera.w, 1080.0f / (2.0f * std::tan(kFovY / 2)), 1e-3f);
}

TEST_F(CullPassTest, GpuListsEqualCpuListsOverFrames) {
    const Field f = randomField(20000, 1);
    create(f);
    std::vector<uint32_t> cpuState;
    const gpu::CullUniforms frames[] = {uniformsFor(kStart, 0, true), uniformsFor(kMoved, 0.1f, false),
                                        uniformsFor(kMoved, 0.1f, false), uniformsFor(kStart, 0.1f, false)};
    size_t fading = 0;
    for (size_t i = 0; i < std::size(frames); ++i) {
        const GpuFrame gpuFrame = run(frames[i]);
        const CpuCullResult cpu = cullOnCpu(f.instances, f.models, frames[i], cpuState);
        ASSERT_EQ(gpuFrame.lists.size(), cpu.lists.size());
        for (size_t l = 0; l < cpu.lists.size(); ++l)
            EXPECT_EQ(gpuFrame.lists[l], cpu.lists[l])
                << "frame " << i << " model " << l / LOD_COUNT << " LOD " << l % LOD_COUNT;
        EXPECT_EQ(gpuFrame.state, cpuState) << "frame " << i;
        for (uint32_t s : cpuState) fading += gpu::lodStateProgress(s) != LOD_STATE_SETTLED;
        if (i == 0) {
            for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) EXPECT_GT(gpuFrame.counts.perLod[lod], 100u) << lod;
            EXPECT_EQ(fading, 0u); // the first frame settles everything
        }
    }
    EXPECT_GT(fading, 10u); // the moves changed LODs, so fades were compared too
}

// With nothing in the depth pyramid the two phases together draw what one
// phase draws, frame after frame: the early phase the plants drawn the
// frame before, the late phase the others, each plant's LOD state moved on
// once (the visible bit aside) and its entries in one phase only.
TEST_F(CullPassTest, TwoPhasesWithAnEmptyPyramidEqualTheCpuReference) {
    const Field f = randomField(20000, 2);
    create(f);
    RenderTarget target = createRenderTarget(ctx, {192, 108}, {.method = AntialiasMethod::none});
    std::vector<uint32_t> cpuState;
    const View views[] = {kStart, kStart, kMoved, kMoved};
    const gpu::CullUniforms frames[] = {uniformsFor(kStart, 0, true), uniformsFor(kStart, 0.1f, false),
                                        uniformsFor(kMoved, 0.1f, false), uniformsFor(kMoved, 0.1f, false)};
    for (size_t i = 0; i < std::size(frames); ++i) {
        const GpuFrame gpuFrame = runTwoPhases(frames[i], views[i], target);
        const CpuCullResult cpu = cullOnCpu(f.instances, f.models, frames[i], cpuState);
        for (size_t l = 0; l < cpu.lists.size(); ++l)
            EXPECT_EQ(gpuFrame.lists[l], cpu.lists[l])
                << "frame " << i << " model " << l / LOD_COUNT << " LOD " << l % LOD_COUNT;
        std::vector<uint32_t> lodState = gpuFrame.state;
        size_t visible = 0;
        for (uint32_t& s : lodState) {
            visible += (s & LOD_STATE_VISIBLE_BIT) != 0;
            s &= ~LOD_STATE_VISIBLE_BIT;
        }
        EXPECT_EQ(lodState, cpuState) << "frame " << i;
        std::set<uint32_t> drawn; // a fading plant has two entries and one bit
        for (const std::vector<uint32_t>& list : cpu.lists)
            for (uint32_t entry : list) drawn.insert(entry & VISIBLE_INDEX_MASK);
        EXPECT_EQ(visible, drawn.size()) << "frame " << i;
        EXPECT_EQ(gpuFrame.counts.occluded, 0u);
    }
    destroyRenderTarget(target);
}

TEST_F(CullPassTest, PlantsBehindTheCameraNeverAppear) {
    const Field f = randomField(20000, 2);
    create(f);
    const GpuFrame frame = run(uniformsFor(kStart, 0, true));
    const glm::vec3 forward = glm::normalize(kStart.target - kStart.position);
    std::set<uint32_t> drawn;
    for (const auto& list : frame.lists)
        for (uint32_t e : list) drawn.insert(e & VISIBLE_INDEX_MASK);
    size_t behind = 0;
    for (uint32_t i = 0; i < f.instances.size(); ++i) {
        const glm::vec4 s = gpu::instanceSphere(f.instances[i], f.models[f.instances[i].ids.x]);
        if (glm::dot(glm::vec3(s) - kStart.position, forward) < -s.w) {
            ++behind;
            EXPECT_EQ(drawn.count(i), 0u) << "instance " << i;
        }
    }
    EXPECT_GT(behind, 5000u);
    EXPECT_GT(drawn.size(), 1000u);
}

TEST_F(CullPassTest, ForcedLodPutsEveryVisiblePlantInThatLod) {
    const Field f = randomField(20000, 3);
    create(f);
    const GpuFrame free = run(uniformsFor(kStart, 0, true));
    for (uint32_t forced = 0; forced < LOD_COUNT; ++forced) {
        const GpuFrame frame = run(uniformsFor(kMoved, 0.1f, false, forced));
        const GpuFrame again = run(uniformsFor(kStart, 0.1f, false, forced));
        for (uint32_t m = 0; m < kModels; ++m)
            for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
                const std::vector<uint32_t>& list = again.lists[m * LOD_COUNT + lod];
                if (lod != forced) {
                    EXPECT_TRUE(list.empty()) << "forced " << forced << " model " << m << " LOD " << lod;
                    continue;
                }
                for (uint32_t e : list) EXPECT_EQ(e >> VISIBLE_INDEX_BITS, VISIBLE_COVERAGE_MAX << 1) << e;
            }
        // Same view, same visible plants: only their LOD changed.
        EXPECT_EQ(entries(again.lists), entries(free.lists)) << forced;
        EXPECT_GT(entries(frame.lists), 0u);
    }
}

// The distance at which a sphere of `radius` projects to `pixels`.
float distanceFor(const gpu::CullUniforms& u, float radius, float pixels) { return 2 * radius * u.camera.w / pixels; }

// One plant of model 0 with a unit sphere around its origin.
Field singlePlant() {
    std::vector<gpu::PlantModel> models = makeModels();
    models.resize(1);
    models[0].sphere = glm::vec4(0, 0, 0, 1);
    return layOut({makeInstance(glm::vec3(0, 0, 0), 0, 1, 0)}, std::move(models));
}

// Camera on the -z axis looking at the plant from `d` metres.
gpu::CullUniforms viewFrom(float d, float dt, bool first) { return uniformsFor({{0, 0, -d}, {0, 0, 0}}, dt, first); }

uint32_t lodOf(const GpuFrame& frame) {
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
        if (!frame.lists[lod].empty()) return lod;
    return LOD_COUNT;
}

TEST_F(CullPassTest, HysteresisKeepsTheLodBetweenTheBoundaries) {
    const Field f = singlePlant();
    create(f);
    const gpu::CullUniforms probe = viewFrom(10, 0, true);
    const float t = f.models[0].lod.x, h = f.models[0].lod.z;
    std::vector<uint32_t> cpuState;
    auto step = [&](float pixels, bool first) {
        const gpu::CullUniforms u = viewFrom(distanceFor(probe, 1, pixels), 1.0f, first);
        const GpuFrame frame = run(u);
        EXPECT_EQ(frame.lists, cullOnCpu(f.instances, f.models, u, cpuState).lists) << pixels;
        return lodOf(frame);
    };
    EXPECT_EQ(step(t * (1 + 2 * h), true), 0u);
    EXPECT_EQ(step(t * (1 - h / 2), false), 0u); // below T but above T(1−h): stays
    EXPECT_EQ(step(t * (1 - 2 * h), false), 1u); // below T(1−h): coarser
    EXPECT_EQ(step(t * (1 + h / 2), false), 1u); // above T but below T(1+h): stays
    EXPECT_EQ(step(t * (1 + 2 * h), false), 0u); // above T(1+h): finer
    // Both boundaries in one frame.
    EXPECT_EQ(step(f.models[0].lod.y * (1 - 2 * h), false), 2u);
    EXPECT_EQ(step(t * (1 + 2 * h), false), 0u);
    // The first frame ignores the previous LOD and the hysteresis.
    EXPECT_EQ(step(t * (1 - h / 2), true), 1u);
}

TEST_F(CullPassTest, FadingPlantIsInBothListsWithCoveragesSummingToMax) {
    const Field f = singlePlant();
    create(f);
    const gpu::CullUniforms probe = viewFrom(10, 0, true);
    const float near = distanceFor(probe, 1, 400), far = distanceFor(probe, 1, 100);
    std::vector<uint32_t> cpuState;
    auto step = [&](float d, float dt, bool first) {
        const gpu::CullUniforms u = viewFrom(d, dt, first);
        const GpuFrame frame = run(u);
        EXPECT_EQ(frame.lists, cullOnCpu(f.instances, f.models, u, cpuState).lists);
        return frame;
    };
    const GpuFrame settled = step(near, 0.01f, true);
    ASSERT_EQ(settled.lists[0], std::vector<uint32_t>{VISIBLE_COVERAGE_MAX << VISIBLE_COVERAGE_SHIFT});

    const GpuFrame half = step(far, kFadeSeconds / 2, false);
    ASSERT_EQ(half.lists[0].size(), 1u);
    ASSERT_EQ(half.lists[1].size(), 1u);
    EXPECT_TRUE(half.lists[2].empty());
    const uint32_t out = half.lists[0][0], in = half.lists[1][0];
    EXPECT_EQ(out & VISIBLE_FADE_IN_BIT, 0u);
    EXPECT_NE(in & VISIBLE_FADE_IN_BIT, 0u);
    EXPECT_EQ((out >> VISIBLE_COVERAGE_SHIFT) + (in >> VISIBLE_COVERAGE_SHIFT), VISIBLE_COVERAGE_MAX);
    EXPECT_NEAR(double(in >> VISIBLE_COVERAGE_SHIFT), 63.5, 1.0);
    EXPECT_EQ(gpu::lodStateFrom(half.state[0]), 0u);
    EXPECT_EQ(gpu::lodStateCurrent(half.state[0]), 1u);

    const GpuFrame done = step(far, kFadeSeconds / 2, false);
    EXPECT_TRUE(done.lists[0].empty());
    EXPECT_EQ(done.lists[1], std::vector<uint32_t>{VISIBLE_COVERAGE_MAX << VISIBLE_COVERAGE_SHIFT});
    EXPECT_EQ(gpu::lodStateProgress(done.state[0]), LOD_STATE_SETTLED);
}

TEST_F(CullPassTest, CulledPlantKeepsItsLodAndSettles) {
    const Field f = singlePlant();
    create(f);
    const gpu::CullUniforms probe = viewFrom(10, 0, true);
    run(viewFrom(distanceFor(probe, 1, 400), 0, true));
    const GpuFrame fading = run(viewFrom(distanceFor(probe, 1, 100), 0.01f, false));
    EXPECT_EQ(gpu::lodStateCurrent(fading.state[0]), 1u);
    EXPECT_LT(gpu::lodStateProgress(fading.state[0]), LOD_STATE_SETTLED);
    // Turned away: nothing drawn, the LOD kept, the fade finished.
    const GpuFrame away = run(uniformsFor({{0, 0, -distanceFor(probe, 1, 400)}, {0, 0, -100}}, 0.01f, false));
    EXPECT_EQ(entries(away.lists), 0u);
    EXPECT_EQ(away.state[0], gpu::lodStatePack(1, 1, LOD_STATE_SETTLED));
}

TEST_F(CullPassTest, DrawCommandsDescribeTheNonEmptyLists) {
    const Field f = randomField(20000, 4);
    create(f);
    run(uniformsFor(kStart, 0, true));
    const GpuFrame frame = run(uniformsFor(kMoved, 0.1f, false));
    const uint32_t templateCount = uint32_t(f.templates.size());
    for (uint32_t drawClass = 0; drawClass < DRAW_CLASS_COUNT; ++drawClass) {
        std::multiset<std::vector<uint32_t>> expected;
        for (uint32_t t = 0; t < templateCount; ++t) {
            const gpu::DrawTemplate& tmpl = f.templates[t];
            const uint32_t n = uint32_t(frame.lists[tmpl.list.x].size());
            const gpu::DrawCommand& all = frame.allCommands[t];
            // The fallback command of every template, empty or not.
            EXPECT_EQ(all.indexCount, tmpl.mesh.x);
            EXPECT_EQ(all.instanceCount, n);
            EXPECT_EQ(all.firstIndex, tmpl.mesh.y);
            EXPECT_EQ(all.vertexOffset, tmpl.mesh.z);
            EXPECT_EQ(all.firstInstance, tmpl.list.y);
            const gpu::PlantModel& model = f.models[tmpl.list.x / LOD_COUNT];
            EXPECT_EQ(all.firstInstance, model.lists[tmpl.list.x % LOD_COUNT]);
            if (tmpl.mesh.w == drawClass && n > 0)
                expected.insert({tmpl.mesh.x, n, tmpl.mesh.y, tmpl.mesh.z, tmpl.list.y});
        }
        ASSERT_EQ(frame.counts.drawsPerClass[drawClass], expected.size()) << drawClass;
        std::multiset<std::vector<uint32_t>> got;
        for (uint32_t i = 0; i < expected.size(); ++i) {
            const gpu::DrawCommand& c = frame.commands[drawClass * templateCount + i];
            got.insert({c.indexCount, c.instanceCount, c.firstIndex, c.vertexOffset, c.firstInstance});
        }
        EXPECT_EQ(got, expected) << drawClass;
        EXPECT_GT(expected.size(), 0u);
    }
    EXPECT_EQ(pass.templatesPerClass[DRAW_IMPOSTOR], kModels);
    EXPECT_EQ(pass.firstTemplateOfClass[DRAW_IMPOSTOR], 4 * kModels);
}

// Records drawClassIndirect for every class on all three paths (count,
// multi-draw fallback, one draw per template) with a trivial pipeline, so
// the validation layer checks buffers, offsets, strides and counts.
TEST_F(CullPassTest, IndirectDrawsOfEveryPathAreValid) {
    const Field f = randomField(2000, 7);
    create(f);
    run(uniformsFor(kStart, 0, true));

    const VkExtent2D extent{16, 16};
    Image target = createImage(
        resources,
        {.extent = extent, .format = VK_FORMAT_R8G8B8A8_UNORM, .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT});
    const std::vector<uint32_t> indices(4096, 0); // every triangle degenerate: cheap to "draw"
    Buffer indexBuffer =
        createDeviceBufferWithData(resources, indices.data(), indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    Buffer frame = createHostBuffer(resources, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(frame.mapped, 0, sizeof(gpu::FrameUniforms));

    // The sky's shaders read the frame in both stages (the view ray per corner).
    const DescriptorBinding table[] = {
        uniformBuffer(BINDING_FRAME_UNIFORMS, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, frame)};
    const VkDescriptorSetLayout setLayout = createSetLayout(resources, table);
    const VkDescriptorSet set = createSet(resources, setLayout, table);
    const VkPipelineLayout layout = createPipelineLayout(resources, setLayout);

    GraphicsPipelineDesc desc;
    desc.vertex = createShaderModule(resources, spirv_sky_vert);
    desc.fragment = createShaderModule(resources, spirv_sky_frag);
    desc.layout = layout;
    desc.colorFormat = target.format;
    desc.depthTest = false;
    desc.depthWrite = false;
    VkPipeline pipeline = createGraphicsPipeline(resources, desc);

    const bool hasCount = ctx.drawIndirectCount, hasMulti = ctx.multiDrawIndirect;
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        recordCullPass(cmd, pass);
        imageBarrier(cmd, target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
        beginColorOnlyRendering(cmd, target.view, VK_ATTACHMENT_LOAD_OP_CLEAR, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
        vkCmdBindIndexBuffer(cmd, indexBuffer.buffer, 0, VK_INDEX_TYPE_UINT32);
        for (int path = 0; path < 3; ++path) {
            ctx.drawIndirectCount = hasCount && path == 0;
            ctx.multiDrawIndirect = hasMulti && path <= 1;
            for (uint32_t drawClass = 0; drawClass < DRAW_CLASS_COUNT; ++drawClass)
                drawClassIndirect(cmd, ctx, pass, drawClass);
        }
        vkCmdEndRendering(cmd);
    });
    ctx.drawIndirectCount = hasCount;
    ctx.multiDrawIndirect = hasMulti;
    EXPECT_TRUE(hasCount) << "lavapipe has drawIndirectCount; the count path went untested";
}

TEST_F(CullPassTest, TwoRunsGiveIdenticalLists) {
    const Field f = randomField(20000, 5);
    create(f);
    const GpuFrame a1 = run(uniformsFor(kStart, 0, true));
    const GpuFrame a2 = run(uniformsFor(kMoved, 0.1f, false));
    const GpuFrame b1 = run(uniformsFor(kStart, 0, true));
    const GpuFrame b2 = run(uniformsFor(kMoved, 0.1f, false));
    EXPECT_EQ(a1.lists, b1.lists);
    EXPECT_EQ(a2.lists, b2.lists);
    EXPECT_EQ(a2.state, b2.state);
    EXPECT_EQ(a1.counts.perModelLod, b1.counts.perModelLod);
}

TEST_F(CullPassTest, MillionInstancesRunWithoutValidationErrors) {
    std::vector<gpu::PlantModel> models = makeModels();
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<gpu::FieldInstance> instances(1u << 20);
    for (gpu::FieldInstance& inst : instances) {
        const float radius = 1000.0f * std::sqrt(unit(rng)), angle = 6.2831853f * unit(rng);
        inst = makeInstance(glm::vec3(radius * std::cos(angle), 0, radius * std::sin(angle)), 6.2831853f * unit(rng),
                            0.5f + unit(rng), uint32_t(unit(rng) * kModels) % kModels);
    }
    const Field f = layOut(std::move(instances), std::move(models));
    create(f);
    run(uniformsFor(kStart, 0, true));
    const auto start = std::chrono::steady_clock::now();
    const GpuFrame frame = run(uniformsFor(kMoved, 1.0f / 60, false));
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ timing   ] cull pass of %zu instances: GPU %.2f ms (timestamps), submit+wait+readback %.2f ms, "
                "%u LOD0 / %u LOD1 / %u LOD2 entries\n",
                f.instances.size(), frame.gpuMilliseconds, wallMs, frame.counts.perLod[0], frame.counts.perLod[1],
                frame.counts.perLod[2]);
    EXPECT_GT(entries(frame.lists), 0u);
}

} // namespace
} // namespace pf::test
