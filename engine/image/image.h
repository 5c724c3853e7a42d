// 8-bit RGBA images in memory and as PNG files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pf {

struct RgbaImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels; // row-major, top row first, 4 bytes a pixel
};

// Writes through a temporary file renamed into place, so a failed write never
// leaves a truncated PNG behind. Throws with the path on failure.
// Output files are written to PATH.partial, then renamed onto PATH, so a
// failure never leaves half a file and never clobbers an existing one.
std::string partialPathOf(const std::string& path);
// Renames PATH.partial onto PATH; on failure removes it and throws, naming PATH.
void finishPartialFile(const std::string& path);

void writePng(const std::string& path, const RgbaImage& image);
// Throws with the path and stb's reason when the file cannot be read.
RgbaImage readPng(const std::string& path);

// Empty when a new file can be created at `path`, otherwise the reason it
// cannot (missing folder, not writable, is a folder). Checked before any work.
std::string outputPathProblem(const std::string& path);

} // namespace pf
