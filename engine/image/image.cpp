#include "engine/image/image.h"

#include "lsystem/common/file_reader.h"
#include "lsystem/common/output_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

namespace pf {
namespace {

// Past any heightmap or texture the renderer reads (a 16384² PNG is far less),
// and within stb's int lengths.
constexpr size_t kMaxImageFileBytes = size_t(1) << 30;

} // namespace

void writePng(const std::string& path, const RgbaImage& image) {
    lsys::OutputFile file(path);
    const auto write = [](void* context, void* data, int size) {
        static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
    };
    const int stride = int(image.width * 4);
    if (!stbi_write_png_to_func(write, &file.stream(), int(image.width), int(image.height), 4, image.pixels.data(),
                                stride))
        throw std::runtime_error("cannot write PNG '" + path + "'");
    file.commit();
}

RgbaImage readPng(const std::string& path, const lsys::MemoryBudget& memory) {
    // Read through readFileUpTo rather than opened by stb, so that a fifo or a
    // device is refused instead of blocking or never ending.
    const lsys::FileBytes file = lsys::readFileUpTo(path, kMaxImageFileBytes);
    if (file.problem != lsys::FileProblem::None)
        throw std::runtime_error("cannot read image '" + path + "': it " +
                                 lsys::fileProblemText(file.problem, kMaxImageFileBytes));
    const auto* bytes = reinterpret_cast<const stbi_uc*>(file.bytes.data());
    const int length = int(file.bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, length, &w, &h, &channels))
        throw std::runtime_error("cannot read image '" + path + "': " + stbi_failure_reason());
    // stb's decoded copy and ours, 4 bytes a pixel each.
    lsys::need(memory, "image", lsys::bytesTimes(uint64_t(w) * uint64_t(h), 8));
    stbi_uc* data = stbi_load_from_memory(bytes, length, &w, &h, &channels, 4);
    if (!data) throw std::runtime_error("cannot read image '" + path + "': " + stbi_failure_reason());
    RgbaImage image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(data, data + size_t(w) * size_t(h) * 4)};
    stbi_image_free(data);
    return image;
}

} // namespace pf
