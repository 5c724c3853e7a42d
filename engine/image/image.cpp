#include "engine/image/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace pf {

std::string partialPathOf(const std::string& path) { return path + ".partial"; }

void finishPartialFile(const std::string& path) {
    const std::string temporary = partialPathOf(path);
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write '" + path + "': " + reason);
    }
}

void writePng(const std::string& path, const RgbaImage& image) {
    const std::string temporary = partialPathOf(path);
    const int stride = int(image.width * 4);
    if (!stbi_write_png(temporary.c_str(), int(image.width), int(image.height), 4, image.pixels.data(), stride)) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write PNG '" + path + "'");
    }
    finishPartialFile(path);
}

RgbaImage readPng(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) throw std::runtime_error("cannot read image '" + path + "': " + stbi_failure_reason());
    RgbaImage image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(data, data + size_t(w) * size_t(h) * 4)};
    stbi_image_free(data);
    return image;
}

std::string outputPathProblem(const std::string& path) {
    namespace fs = std::filesystem;
    if (path.empty()) return "the output path is empty";
    const fs::path p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec)) return "'" + path + "' is a folder";
    const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec)) return "folder '" + parent.string() + "' does not exist";
    if (access(parent.c_str(), W_OK) != 0) return "folder '" + parent.string() + "' is not writable";
    if (fs::exists(p, ec) && access(p.c_str(), W_OK) != 0) return "'" + path + "' is not writable";
    return {};
}

} // namespace pf
