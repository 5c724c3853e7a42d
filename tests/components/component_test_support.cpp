#include "component_test_support.h"

#include "test_folder.h"

#include <fstream>

namespace lsys::components::test {

std::filesystem::path writeComponentFile(std::string_view name, std::string_view text) {
    const std::filesystem::path file = pf::test::testFolder("plantfield_component_tests") / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

} // namespace lsys::components::test
