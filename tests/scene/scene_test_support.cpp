#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pf::test {

std::filesystem::path testFolder() { return testFolder("plantfield_scene_tests"); }

std::filesystem::path writeFile(const std::string& name, std::string_view text) {
    const std::filesystem::path path = testFolder() / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string lineColumnOf(std::string_view text, std::string_view needle) {
    const size_t offset = text.find(needle);
    EXPECT_NE(offset, std::string_view::npos) << needle;
    size_t line = 1, column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        column = text[i] == '\n' ? 1 : column + 1;
        line += text[i] == '\n';
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

} // namespace pf::test
