// Writing scene files for tests into a folder of their own.
#pragma once

#include "engine/scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>

// An L-system file that exists, as a JSON string member.
#define PF_BUSH_LSYSTEM "\"lsystem\": \"" PLANTFIELD_DATA_DIR "/plants/stochastic_bush.lsys\""

namespace pf::test {

// A fresh folder for the running test (ctest runs tests in parallel).
std::filesystem::path testFolder();

// Writes text to testFolder()/name and returns the path.
std::filesystem::path writeFile(const std::string& name, std::string_view text);

// "line:column" of the first occurrence of needle in text, counted
// independently of the loader.
std::string lineColumnOf(std::string_view text, std::string_view needle);

} // namespace pf::test
