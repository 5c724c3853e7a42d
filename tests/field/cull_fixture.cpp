#include "cull_fixture.h"

#include "engine/vk/depth_pyramid.h"
#include "engine/vk/target_pass.h"

#include "engine/vk/vk_check.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace pf::test {

glm::mat4 viewMatrix(const View& v) { return glm::lookAtRH(v.position, v.target, glm::vec3(0, 1, 0)); }

glm::mat4 projection() { return glm::perspectiveRH_ZO(kFovY, 16.0f / 9.0f, 0.1f, 1000.0f); }

glm::mat4 viewProj(const View& v) { return projection() * viewMatrix(v); }

std::vector<gpu::PlantModel> makeModels() {
    std::vector<gpu::PlantModel> models(kModels);
    for (uint32_t m = 0; m < kModels; ++m) {
        const float r = 1.0f + 0.7f * float(m);
        models[m].sphere = glm::vec4(0.3f * float(m), r, -0.2f * float(m), r);
        models[m].boxMin = glm::vec4(-r, 0, -r, 0);
        models[m].boxMax = glm::vec4(r, 2 * r, r, 0);
        models[m].lod = glm::vec4(200.0f, 40.0f, 0.1f, kFadeSeconds);
    }
    return models;
}

std::vector<gpu::DrawTemplate> makeTemplates(const std::vector<gpu::PlantModel>& models) {
    std::vector<gpu::DrawTemplate> templates;
    for (uint32_t drawClass = 0; drawClass < DRAW_CLASS_COUNT; ++drawClass)
        for (uint32_t m = 0; m < models.size(); ++m)
            for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
                if ((lod == LOD_IMPOSTOR) != (drawClass == DRAW_IMPOSTOR)) continue;
                gpu::DrawTemplate t{};
                t.mesh = glm::uvec4(3 * (1 + m + 10 * lod + 100 * drawClass), 1000 * m + 100 * lod + 10 * drawClass,
                                    64 * m + lod, drawClass);
                t.list = glm::uvec4(m * LOD_COUNT + lod, models[m].lists[lod], 0, 0);
                templates.push_back(t);
            }
    return templates;
}

gpu::FieldInstance makeInstance(glm::vec3 position, float yaw, float scale, uint32_t model) {
    gpu::FieldInstance inst{};
    inst.positionScale = glm::vec4(position, scale);
    inst.orientation = glm::vec4(yaw, 0, 0, 0);
    inst.ids = glm::uvec4(model, model, 0, 0);
    return inst;
}

ExactSphere exactSphere(const gpu::FieldInstance& inst, const gpu::PlantModel& model) {
    const double yaw = inst.orientation.x, c = std::cos(yaw), s = std::sin(yaw), scale = inst.positionScale.w;
    const glm::dvec3 local = glm::dvec3(model.sphere) * scale;
    return {glm::dvec3(inst.positionScale) + glm::dvec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z),
            model.sphere.w * scale};
}

bool grazesPlane(const ExactSphere& s, const glm::vec4& plane) {
    return std::abs(glm::dot(glm::dvec3(plane), s.centre) + plane.w + s.radius) < 1e-4 * (1.0 + glm::length(s.centre));
}

bool nearBoundary(double value, double boundary) { return std::abs(value - boundary) < 1e-4 * boundary; }

std::vector<gpu::FieldInstance> randomInstances(uint32_t n, uint32_t seed,
                                                const std::function<bool(const gpu::FieldInstance&)>& keep) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<gpu::FieldInstance> out;
    out.reserve(n);
    while (out.size() < n) {
        const float radius = 300.0f * unit(rng), angle = 6.2831853f * unit(rng);
        const gpu::FieldInstance inst =
            makeInstance(glm::vec3(radius * std::cos(angle), 0.5f * unit(rng), radius * std::sin(angle)),
                         6.2831853f * unit(rng), 0.5f + unit(rng), uint32_t(unit(rng) * kModels) % kModels);
        if (keep(inst)) out.push_back(inst);
    }
    return out;
}

Field layOut(std::vector<gpu::FieldInstance> instances, std::vector<gpu::PlantModel> models) {
    Field f{std::move(instances), std::move(models), {}};
    assignVisibleLists(f.models, f.instances);
    f.templates = makeTemplates(f.models);
    return f;
}

void CullPassTest::create(const Field& f, CullKind kind, const Buffer* near) {
    field = &f;
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    instances = createDeviceBufferWithData(resources, f.instances.data(),
                                           f.instances.size() * sizeof(gpu::FieldInstance), storage);
    models = createDeviceBufferWithData(resources, f.models.data(), f.models.size() * sizeof(gpu::PlantModel), storage);
    CullPassInputs inputs;
    inputs.kind = kind;
    inputs.instances = &instances;
    inputs.models = &models;
    inputs.instanceCount = uint32_t(f.instances.size());
    inputs.modelCount = uint32_t(f.models.size());
    inputs.templates = f.templates;
    inputs.near = near;
    pass = createCullPass(resources, inputs);
    host = createHostBuffer(resources, pass.visible.size + pass.commands.size + pass.allCommands.size + pass.state.size,
                            VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = 2;
    VK_CHECK(vkCreateQueryPool(ctx.device, &queryInfo, nullptr, &queries));
}

void CullPassTest::TearDown() {
    if (ctx.device) vkDestroyQueryPool(ctx.device, queries, nullptr);
    GpuTest::TearDown();
}

bool CullPassTest::hasTimestamps() {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &n, families.data());
    return families[ctx.queueFamily].timestampValidBits > 0;
}

GpuFrame CullPassTest::run(const gpu::CullUniforms& uniforms) {
    setCullUniforms(pass, uniforms);
    return record([&](VkCommandBuffer cmd) { recordCullPass(cmd, pass); });
}

GpuFrame CullPassTest::run(const gpu::ShadowCullUniforms& uniforms) {
    setCullUniforms(pass, uniforms);
    return record([&](VkCommandBuffer cmd) { recordCullPass(cmd, pass); });
}

GpuFrame CullPassTest::runTwoPhases(const gpu::CullUniforms& uniforms, const View& view, const RenderTarget& target) {
    gpu::CullUniforms u = uniforms;
    const glm::uvec2 viewport(target.extent.width, target.extent.height);
    setOcclusionUniforms(u, viewMatrix(view), projection(), viewport, 0.1f, target.pyramid.levels);
    setCullUniforms(pass, u);
    return record([&](VkCommandBuffer cmd) {
        recordCullPass(cmd, pass, CULL_PHASE_EARLY);
        beginTargetPass(cmd, target, TargetPassPart::first); // depth cleared to 1 and stored
        vkCmdEndRendering(cmd);
        recordDepthPyramid(cmd, target.pyramid);
        recordCullPass(cmd, pass, CULL_PHASE_LATE, target.pyramid.readSet);
    });
}

GpuFrame CullPassTest::record(const std::function<void(VkCommandBuffer)>& recordCull) {
    const bool timed = hasTimestamps();
    const VkBufferCopy visibleRegion{0, 0, pass.visible.size};
    const VkBufferCopy commandsRegion{0, visibleRegion.size, pass.commands.size};
    const VkBufferCopy allRegion{0, commandsRegion.dstOffset + commandsRegion.size, pass.allCommands.size};
    const VkBufferCopy stateRegion{0, allRegion.dstOffset + allRegion.size, pass.state.size};
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        if (timed) {
            vkCmdResetQueryPool(cmd, queries, 0, 2);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries, 0);
        }
        if (clusters) recordClusterPass(cmd, *clusters);
        recordCull(cmd);
        if (timed) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries, 1);
        // recordCullPass's last compute barrier already covers copies.
        vkCmdCopyBuffer(cmd, pass.visible.buffer, host.buffer, 1, &visibleRegion);
        vkCmdCopyBuffer(cmd, pass.commands.buffer, host.buffer, 1, &commandsRegion);
        vkCmdCopyBuffer(cmd, pass.allCommands.buffer, host.buffer, 1, &allRegion);
        vkCmdCopyBuffer(cmd, pass.state.buffer, host.buffer, 1, &stateRegion);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    });

    GpuFrame out;
    out.counts = readCullCounts(pass);
    const auto* bytes = static_cast<const uint8_t*>(host.mapped);
    const auto* visible = reinterpret_cast<const uint32_t*>(bytes);
    out.lists.resize(field->models.size() * LOD_COUNT);
    for (uint32_t m = 0; m < field->models.size(); ++m)
        for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
            std::vector<uint32_t>& list = out.lists[m * LOD_COUNT + lod];
            const uint32_t first = field->models[m].lists[lod];
            list.assign(visible + first, visible + first + out.counts.perModelLod[m * LOD_COUNT + lod]);
            std::sort(list.begin(), list.end());
        }
    const uint32_t templateCount = pass.templateCount;
    out.commands.resize(size_t(DRAW_CLASS_COUNT) * templateCount);
    std::memcpy(out.commands.data(), bytes + commandsRegion.dstOffset, out.commands.size() * sizeof(gpu::DrawCommand));
    out.allCommands.resize(templateCount);
    std::memcpy(out.allCommands.data(), bytes + allRegion.dstOffset, templateCount * sizeof(gpu::DrawCommand));
    out.state.resize(pass.state.size / 4);
    std::memcpy(out.state.data(), bytes + stateRegion.dstOffset, pass.state.size);
    if (timed) {
        uint64_t stamps[2];
        VK_CHECK(vkGetQueryPoolResults(ctx.device, queries, 0, 2, sizeof(stamps), stamps, sizeof(uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        out.gpuMilliseconds = double(stamps[1] - stamps[0]) * ctx.properties.limits.timestampPeriod * 1e-6;
    }
    return out;
}

} // namespace pf::test
