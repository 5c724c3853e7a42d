// Writing scene files for tests into a folder of their own.
#pragma once

#include "engine/scene/scene.h"
#include "test_folder.h"

#include <filesystem>
#include <string>
#include <string_view>

// An L-system file that exists, as a JSON string member.
#define PF_BUSH_LSYSTEM "\"lsystem\": \"" PLANTFIELD_DATA_DIR "/plants/stochastic_bush.lsys\""

namespace pf::test {

// The running test's folder of scene files.
std::filesystem::path testFolder();

// Writes text to testFolder()/name and returns the path.
std::filesystem::path writeFile(const std::string& name, std::string_view text);

// "line:column" of the first occurrence of needle in text, counted
// independently of the loader.
std::string lineColumnOf(std::string_view text, std::string_view needle);

} // namespace pf::test
