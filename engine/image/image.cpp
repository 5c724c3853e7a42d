#include "engine/image/image.h"

#include "lsystem/common/file_reader.h"
#include "lsystem/common/output_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

namespace pf {

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
    lsys::noteFileRead(path); // stb opens it, not readFileUpTo: logged here for the loads that list their files
    int w = 0, h = 0, channels = 0;
    if (!stbi_info(path.c_str(), &w, &h, &channels))
        throw std::runtime_error("cannot read image '" + path + "': " + stbi_failure_reason());
    // stb's decoded copy and ours, 4 bytes a pixel each.
    lsys::need(memory, "image", lsys::bytesTimes(uint64_t(w) * uint64_t(h), 8));
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) throw std::runtime_error("cannot read image '" + path + "': " + stbi_failure_reason());
    RgbaImage image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(data, data + size_t(w) * size_t(h) * 4)};
    stbi_image_free(data);
    return image;
}

} // namespace pf
