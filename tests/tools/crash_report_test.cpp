// tools/crash_report.h: a fatal signal prints the tool's name, the signal and
// the stack, and still ends the process by that signal. SIGILL stands for
// them all: the sanitizers leave it unhandled, so the check runs under them too.

#include "tools/crash_report.h"

#include <gtest/gtest.h>

#include <csignal>

namespace {

TEST(CrashReport, AFatalSignalPrintsTheStackAndEndsTheProcessByIt) {
    EXPECT_EXIT(
        {
            tools::reportCrashes("crashing_tool");
            std::raise(SIGILL);
        },
        ::testing::KilledBySignal(SIGILL), "crashing_tool: fatal signal SIGILL; the stack:\n.*crash_report_tests");
}

TEST(CrashReport, WithoutItTheSignalPrintsNothing) {
    EXPECT_EXIT(std::raise(SIGILL), ::testing::KilledBySignal(SIGILL), "^$");
}

TEST(CrashReport, AHandlerAlreadyInstalledIsKept) {
    EXPECT_EXIT(
        {
            std::signal(SIGILL, [](int) { std::_Exit(3); });
            tools::reportCrashes("crashing_tool");
            std::raise(SIGILL);
        },
        ::testing::ExitedWithCode(3), "^$");
}

} // namespace
