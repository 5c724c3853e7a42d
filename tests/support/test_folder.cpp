#include "test_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace pf::test {

std::filesystem::path testFolder(std::string_view area) {
    const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
        if (c == '/') c = '_';
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / area / name;
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace pf::test
