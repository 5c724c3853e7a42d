// The output rule through a tool (lsystem/common/output_file.h): a command
// whose output is one of its inputs must be refused with exit 2 and a message
// saying so, and leave the input byte for byte as it was.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace pf::test {

// testFolder(area), emptied: what a previous run left would hide a write.
std::filesystem::path emptyTestFolder(std::string_view area);

// scene.json in `dir`: a small terrain and two bushes of the bush.lsys copied
// beside it from the `data` folder; its path.
std::filesystem::path bushScene(const std::filesystem::path& dir, const std::filesystem::path& data);

// Runs `command` and expects the refusal, `input` unchanged (GoogleTest
// failures naming the command otherwise).
void expectRefusedAsInput(const std::string& command, const std::filesystem::path& input);

} // namespace pf::test
