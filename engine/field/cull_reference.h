// The cull pass's decisions on the CPU (docs/CULLING.md): the visible lists
// of the per-plant cull and LOD (shaders/shared/lod_select.h) and the late phase's
// occlusion test (shaders/shared/occlusion_test.h), running the shaders' own
// functions, the references the tests check the GPU pass against. CPU only.
#pragma once

#include "shaders/shared/field_layouts.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace pf {

// The cull's decision on the CPU: the LOD list entries instance i gets this
// frame, updating state.
struct CpuCullResult {
    std::vector<std::vector<uint32_t>> lists; // [model · LOD_COUNT + lod] visible entries, sorted
};
// A run of plants the cull goes over (one near leaf); `restart`: as on a first frame.
struct CpuNearRange {
    uint32_t first = 0, count = 0;
    bool restart = false;
};
CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state);
// Over these plants only (the others keep their state).
CpuCullResult cullOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                        const gpu::CullUniforms& uniforms, std::vector<uint32_t>& state,
                        std::span<const CpuNearRange> near);

// The late phase's occlusion test on the CPU (shaders/shared/occlusion_test.h):
// true when the world-space sphere (xyz centre, w radius) lies behind every
// pixel of its screen rectangle in `pyramid` (depthPyramidOnCpu's levels),
// with the uniforms' view, projection and viewport.
bool sphereOccludedOnCpu(const glm::vec4& sphere, const gpu::CullUniforms& uniforms,
                         const std::vector<std::vector<float>>& pyramid);

} // namespace pf
