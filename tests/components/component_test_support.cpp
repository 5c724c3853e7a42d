#include "component_test_support.h"

#include <fstream>

namespace lsys::components::test {

std::filesystem::path writeComponentFile(std::string_view name, std::string_view text) {
    const std::filesystem::path folder = std::filesystem::current_path() / "component_files";
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

} // namespace lsys::components::test
