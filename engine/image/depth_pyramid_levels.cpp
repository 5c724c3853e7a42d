#include "engine/image/depth_pyramid_levels.h"

#include <algorithm>
#include <cstddef>

namespace pf {

std::vector<PixelExtent> depthPyramidExtents(PixelExtent extent) {
    std::vector<PixelExtent> extents;
    do {
        extent = {(extent.width + 1) / 2, (extent.height + 1) / 2};
        extents.push_back(extent);
    } while (extent.width > 1 || extent.height > 1);
    return extents;
}

std::vector<std::vector<float>> depthPyramidOnCpu(const std::vector<float>& depth, PixelExtent extent) {
    std::vector<std::vector<float>> levels;
    PixelExtent sourceExtent = extent;
    for (const PixelExtent& e : depthPyramidExtents(extent)) {
        const std::vector<float>& source = levels.empty() ? depth : levels.back();
        std::vector<float> level(size_t(e.width) * e.height);
        auto at = [&](uint32_t x, uint32_t y) {
            return source[size_t(std::min(y, sourceExtent.height - 1)) * sourceExtent.width +
                          std::min(x, sourceExtent.width - 1)];
        };
        for (uint32_t y = 0; y < e.height; ++y)
            for (uint32_t x = 0; x < e.width; ++x)
                level[size_t(y) * e.width + x] = std::max(std::max(at(2 * x, 2 * y), at(2 * x + 1, 2 * y)),
                                                          std::max(at(2 * x, 2 * y + 1), at(2 * x + 1, 2 * y + 1)));
        levels.push_back(std::move(level));
        sourceExtent = e;
    }
    return levels;
}

} // namespace pf
