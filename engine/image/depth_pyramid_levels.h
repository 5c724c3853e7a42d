// The levels of a depth pyramid (engine/vk/depth_pyramid.h, docs/CULLING.md
// "The depth pyramid") on the CPU: their sizes over a depth buffer, and the
// reduction itself, the reference the GPU's is tested against and the late
// cull's occlusion test is checked with (sphereOccludedOnCpu). Level 0 is
// half the depth buffer, each level half the one below, rounding up, down to
// 1×1; each texel holds the farthest depth of the pixels under it, a level
// of odd size clamping its reads at the last row and column.
#pragma once

#include <cstdint>
#include <vector>

namespace pf {

struct PixelExtent {
    uint32_t width = 0;
    uint32_t height = 0;
};

// Levels of the pyramid over a depth buffer of `extent`.
std::vector<PixelExtent> depthPyramidExtents(PixelExtent extent);

// The levels of a one-sample depth buffer of `extent` (row-major), each row-major.
std::vector<std::vector<float>> depthPyramidOnCpu(const std::vector<float>& depth, PixelExtent extent);

} // namespace pf
