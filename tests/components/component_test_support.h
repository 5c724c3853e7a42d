#pragma once
// Writing component files for the tests to read.

#include <filesystem>
#include <string_view>

namespace lsys::components::test {

// Writes text to a file of this name in the running test's own folder and
// returns its path.
std::filesystem::path writeComponentFile(std::string_view name, std::string_view text);

} // namespace lsys::components::test
