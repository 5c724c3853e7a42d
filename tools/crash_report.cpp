#include "tools/crash_report.h"

#include <execinfo.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <initializer_list>

namespace tools {
namespace {

const char* reportingTool = "";

// The handler may only call async-signal-safe functions: write, and
// backtrace once libgcc is loaded (reportCrashes loads it).
void writeText(const char* text) {
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, text, std::strlen(text));
}

const char* signalName(int signal) {
    switch (signal) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    default: return "signal";
    }
}

void onFatalSignal(int signal) {
    writeText("\n");
    writeText(reportingTool);
    writeText(": fatal signal ");
    writeText(signalName(signal));
    writeText("; the stack:\n");
    void* frames[64];
    backtrace_symbols_fd(frames, backtrace(frames, 64), STDERR_FILENO);
    // SA_RESETHAND restored the default action; the signal is blocked while
    // this runs, so it arrives on return and ends the process (a raised
    // signal, unlike a fault, would not repeat by itself).
    std::raise(signal);
}

// A stack overflow leaves no stack to run the handler on.
alignas(16) char alternateStack[64 * 1024];

} // namespace

void reportCrashes(const char* tool) {
    reportingTool = tool;
    void* frame[1];
    backtrace(frame, 1); // the first call loads libgcc, which allocates: not in the handler
    stack_t stack{};
    stack.ss_sp = alternateStack;
    stack.ss_size = sizeof alternateStack;
    sigaltstack(&stack, nullptr);
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        struct sigaction current {};
        sigaction(signal, nullptr, &current);
        if (current.sa_handler != SIG_DFL || (current.sa_flags & SA_SIGINFO)) continue;
        struct sigaction report {};
        report.sa_handler = onFatalSignal;
        report.sa_flags = SA_RESETHAND | SA_ONSTACK;
        sigemptyset(&report.sa_mask);
        sigaction(signal, &report, nullptr);
    }
}

} // namespace tools
