// 8-bit RGBA images in memory and as PNG files.
#pragma once

#include "lsystem/common/memory_budget.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pf {

struct RgbaImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels; // row-major, top row first, 4 bytes a pixel
};

// Writes whole or not at all, only over a regular file (lsys::OutputFile).
// Throws with the path on failure.
void writePng(const std::string& path, const RgbaImage& image);
// Throws with the path and stb's reason when the file cannot be read, and
// lsys::MemoryBudgetError (stage "image") when its pixels, decoded and kept,
// would not fit `memory`: checked from the file's header before decoding.
RgbaImage readPng(const std::string& path, const lsys::MemoryBudget& memory = lsys::machineMemoryBudget());

} // namespace pf
