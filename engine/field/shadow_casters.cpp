#include "engine/field/shadow_casters.h"

#include "engine/field/cull_uniforms.h"
#include "shaders/shared/shadow_select.h"

#include <algorithm>

namespace pf {

gpu::ShadowCullUniforms makeShadowCullUniforms(const glm::mat4& boxViewProj, const glm::mat4& cameraViewProj,
                                               const ShadowView& frame, const ShadowView& cache,
                                               const ShadowCacheSettings& settings, uint32_t mode) {
    gpu::ShadowCullUniforms u{};
    const std::array<glm::vec4, 6> box = frustumPlanes(boxViewProj);
    std::copy(box.begin(), box.end(), u.box);
    const std::array<glm::vec4, 6> view = frustumPlanes(cameraViewProj);
    std::copy(view.begin(), view.end(), u.view);
    u.sun = glm::vec4(frame.sunDirection, 0.0f);
    u.camera = glm::vec4(frame.camera, frame.pixelsPerMetre);
    u.counts = glm::uvec4(0, 0, frame.forcedLod, mode);
    // A centimetre and a thousandth wider than shadowCacheServes allows, so
    // float rounding in the distances cannot let the cache hold a plant that
    // a frame it serves sees otherwise.
    u.cacheCamera = glm::vec4(cache.camera, settings.reach + 0.01f);
    const float tolerance = settings.pixelTolerance + 0.001f;
    u.cachePixels =
        glm::vec4(cache.pixelsPerMetre * (1.0f - tolerance), cache.pixelsPerMetre * (1.0f + tolerance), 0.0f, 0.0f);
    return u;
}

CpuCullResult shadowCastersOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                                 const gpu::ShadowCullUniforms& uniforms) {
    CpuCullResult out;
    out.lists.resize(models.size() * LOD_COUNT);
    for (uint32_t i = 0; i < instances.size(); ++i) {
        const uint32_t m = instances[i].ids.x;
        const uint32_t lod = gpu::shadowCasterLod(instances[i], models[m], uniforms);
        if (lod != SHADOW_NOT_CAST)
            out.lists[size_t(m) * LOD_COUNT + lod].push_back(gpu::visibleEntry(i, 0, VISIBLE_COVERAGE_MAX));
    }
    for (std::vector<uint32_t>& list : out.lists) std::sort(list.begin(), list.end());
    return out;
}

} // namespace pf
