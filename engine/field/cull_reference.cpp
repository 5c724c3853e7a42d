#include "engine/field/cull_reference.h"

#include "engine/image/depth_pyramid_levels.h"
#include "shaders/shared/lod_select.h"
#include "shaders/shared/occlusion_test.h"

#include <algorithm>

namespace pf {

CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state) {
    const CpuNearRange all{0, uint32_t(instances.size()), false};
    return cullOnCpu(instances, models, uniforms, state, std::span(&all, 1));
}

CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state,
                        std::span<const CpuNearRange> near) {
    state.resize(instances.size(), LOD_STATE_SETTLED << 8);
    CpuCullResult out;
    out.lists.resize(models.size() * LOD_COUNT);
    const glm::vec4* f = uniforms.frustum;
    for (const CpuNearRange& range : near)
        for (uint32_t i = range.first; i < range.first + range.count; ++i) {
            const gpu::FieldInstance& inst = instances[i];
            const uint32_t m = inst.ids.x;
            const gpu::PlantModel& model = models[m];
            const glm::vec4 sphere = gpu::instanceSphere(inst, model);
            const float pixels = gpu::projectedPixels(sphere, uniforms.camera);
            const bool inside = gpu::sphereInFrustum(sphere, f[0], f[1], f[2], f[3], f[4], f[5]) &&
                                gpu::largeEnoughToDraw(pixels, model, uniforms.counts.z);
            const uint32_t next = gpu::nextLodState(state[i], inside, pixels, model.lod, uniforms.counts.z,
                                                    uniforms.counts.w == 1u || range.restart, uniforms.timing.x);
            state[i] = next;
            if (!inside) continue;
            const uint32_t progress = gpu::lodStateProgress(next);
            std::vector<uint32_t>* lists = &out.lists[size_t(m) * LOD_COUNT];
            if (progress == LOD_STATE_SETTLED) {
                lists[gpu::lodStateCurrent(next)].push_back(gpu::visibleEntry(i, 0, VISIBLE_COVERAGE_MAX));
                continue;
            }
            const uint32_t coverageIn = gpu::fadeInCoverage(progress);
            lists[gpu::lodStateCurrent(next)].push_back(gpu::visibleEntry(i, VISIBLE_FADE_IN_BIT, coverageIn));
            lists[gpu::lodStateFrom(next)].push_back(gpu::visibleEntry(i, 0, VISIBLE_COVERAGE_MAX - coverageIn));
        }
    for (std::vector<uint32_t>& list : out.lists) std::sort(list.begin(), list.end());
    return out;
}

bool sphereOccludedOnCpu(const glm::vec4& sphere, const gpu::CullUniforms& u,
                         const std::vector<std::vector<float>>& pyramid) {
    const glm::vec4 viewSphere(glm::vec3(u.view * glm::vec4(glm::vec3(sphere), 1.0f)), sphere.w);
    if (gpu::sphereNearCamera(viewSphere, u.viewport.z)) return false;
    const glm::uvec4 pixels =
        gpu::rectPixels(gpu::sphereScreenRect(viewSphere, u.projection), glm::vec2(u.viewport.x, u.viewport.y));
    const uint32_t level = gpu::pyramidLevel(pixels, uint32_t(u.viewport.w));
    const glm::uvec4 t = pixels >> (level + 1u);
    const uint32_t width = depthPyramidExtents({uint32_t(u.viewport.x), uint32_t(u.viewport.y)})[level].width;
    auto at = [&](uint32_t x, uint32_t y) { return pyramid[level][size_t(y) * width + x]; };
    const float farthest = std::max(std::max(at(t.x, t.y), at(t.z, t.y)), std::max(at(t.x, t.w), at(t.z, t.w)));
    return !(gpu::sphereNearestDepth(viewSphere, u.projection) <= farthest);
}

} // namespace pf
