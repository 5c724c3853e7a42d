// The sun's shadow casters (shaders/shared/shadow_select.h), picked on the GPU by a
// CullKind::ShadowCasters cull pass over the instances: the plants whose
// bounding sphere meets the sun's box, in view of the camera or not, split
// between the cache of static casters (impostors for every camera the cache
// serves, drawn at rest) and the frame's casters drawn on top of it every
// frame (the nearer plants: full meshes, which sway with their skeletons,
// where the camera targets LOD0, impostors elsewhere). CPU only.
#pragma once

#include "engine/field/cull_reference.h"
#include "engine/field/shadow_cache.h"

#include <span>

namespace pf {

// The uniforms of a shadow-caster pass over the box of `boxViewProj` (the
// cache's or the frame's view-projection) in `mode` (SHADOW_CULL_CACHE or
// SHADOW_CULL_FRAME), for the frame's camera (its view-projection
// `cameraViewProj`) and the cache that serves it.
gpu::ShadowCullUniforms makeShadowCullUniforms(const glm::mat4& boxViewProj, const glm::mat4& cameraViewProj,
                                               const ShadowView& frame, const ShadowView& cache,
                                               const ShadowCacheSettings& settings, uint32_t mode);

// The same decision on the CPU, the reference the tests check the GPU
// against: the entries of each (model, LOD) list, sorted.
CpuCullResult shadowCastersOnCpu(std::span<const gpu::FieldInstance> instances, std::span<const gpu::PlantModel> models,
                                 const gpu::ShadowCullUniforms& uniforms);

} // namespace pf
