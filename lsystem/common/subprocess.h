#pragma once
// Runs a helper program with text on its standard input, collecting its
// standard output and error: the C preprocessor cpfg files are read through
// (runProcess, all input at once) and the video encoder plantfield streams
// frames into (Process, input written piece by piece).

#include <array>
#include <chrono>
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

// A running program whose standard input is written piece by piece while its
// output and error are collected, so that it never blocks on a full pipe.
// The limits hold as for runProcess, the time limit counted from the start.
class Process {
public:
    explicit Process(const std::vector<std::string>& argv, const ProcessLimits& limits = {});
    Process(const Process&) = delete;
    Process& operator=(const Process&) = delete;
    ~Process(); // a program not finished is killed and waited for

    bool started() const { return result_.started; }
    // Writes all of `data`; false when the program no longer reads it (it
    // exited, or was killed past a limit; finish() says which).
    bool write(std::string_view data);
    // Closes its standard input and waits for it to end.
    ProcessResult finish();

private:
    // Polls until `input` is written (or can no longer be), or, with no
    // input left, until the program closes its output and error.
    void pump(std::string_view input);

    std::string program_;
    ProcessLimits limits_;
    std::chrono::steady_clock::time_point deadline_;
    int pid_ = -1;
    std::array<int, 3> ends_{-1, -1, -1}; // the caller's ends of its input, output and error
    ProcessResult result_;
    std::string stopped_; // why the program was killed
    bool finished_ = false;
};

} // namespace lsys
