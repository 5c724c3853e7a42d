#pragma once
// Runs a helper program (the C preprocessor cpfg files are read through)
// with text on its standard input, collecting its standard output and error.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace lsys {

struct ProcessResult {
    bool started = false; // false: the program could not be run (see `failure`)
    int exitCode = -1;    // the exit status; -1 when it was killed by a signal
    std::string out, err;
    std::string failure; // why it did not start or was stopped, for messages
};

struct ProcessLimits {
    size_t maxOutputBytes = size_t(64) << 20; // standard output and error together
    int timeoutSeconds = 60;                  // wall-clock time, and CPU time
    size_t maxMemoryBytes = size_t(1) << 30;  // the program's address space
};

// Runs argv[0] (looked up in PATH) with `input` on its standard input. A
// program that writes more than the limit or runs longer is killed: `failure`
// says which and exitCode is -1. Never raises SIGPIPE in the caller, whatever
// the program does.
ProcessResult runProcess(const std::vector<std::string>& argv, std::string_view input,
                         const ProcessLimits& limits = {});

} // namespace lsys
