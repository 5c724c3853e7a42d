// A folder of files for the running test alone.
#pragma once

#include <filesystem>
#include <string_view>

namespace pf::test {

// temp/area/Suite.Test, created if missing. ctest runs every test as its own
// process, in parallel, so files two tests share by name would be written by
// one while the other reads them.
std::filesystem::path testFolder(std::string_view area);

} // namespace pf::test
