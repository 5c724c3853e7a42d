#include "input_file.h"

#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace pf::fuzz {
namespace fs = std::filesystem;

namespace {

fs::path inputFolder() {
    const fs::path folder = fs::temp_directory_path() / ("plantfield-fuzz-" + std::to_string(getpid()));
    for (const char* shipped : {"plants", "meshes", "terrain"}) {
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (!fs::exists(fs::symlink_status(folder / shipped)))
            fs::create_directory_symlink(fs::path(PLANTFIELD_DATA_DIR) / shipped, folder / shipped);
    }
    return folder;
}

} // namespace

fs::path writeInputFile(const uint8_t* data, size_t size, const std::string& relative) {
    static const fs::path folder = inputFolder();
    const fs::path path = folder / relative;
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
    return path;
}

} // namespace pf::fuzz
