// Runs a shell command for CLI tests and returns its exit code and output.
#pragma once

#include <string>

namespace pf::test {

struct CommandResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

CommandResult runCommand(const std::string& command);

} // namespace pf::test
