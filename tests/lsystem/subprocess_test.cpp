// runProcess (lsystem/subprocess.h), which runs the C preprocessor: input and
// output larger than a pipe holds, programs that stop reading, write without
// end or never finish, and programs that do not exist.

#include <gtest/gtest.h>

#include "lsystem/subprocess.h"

namespace lsys {
namespace {

TEST(Subprocess, InputAndOutputLargerThanAPipeHolds) {
    std::string input;
    for (int i = 0; input.size() < (size_t(3) << 20); ++i) input += "line " + std::to_string(i) + "\n";
    const ProcessResult result = runProcess({"cat"}, input);
    ASSERT_TRUE(result.started) << result.failure;
    EXPECT_EQ(result.exitCode, 0);
    EXPECT_TRUE(result.failure.empty()) << result.failure;
    EXPECT_EQ(result.out, input);
}

TEST(Subprocess, StandardErrorAndExitStatusAreKept) {
    const ProcessResult result = runProcess({"sh", "-c", "cat >/dev/null; echo oops >&2; exit 3"}, "ignored");
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_EQ(result.err, "oops\n");
    EXPECT_TRUE(result.out.empty());
}

// The program exits without reading: writing to it must not kill the caller with SIGPIPE.
TEST(Subprocess, AProgramThatStopsReadingDoesNotStopTheCaller) {
    const ProcessResult result = runProcess({"true"}, std::string(size_t(8) << 20, 'x'));
    EXPECT_TRUE(result.started);
    EXPECT_EQ(result.exitCode, 0);
}

TEST(Subprocess, OutputPastTheLimitStopsTheProgram) {
    ProcessLimits limits;
    limits.maxOutputBytes = size_t(1) << 20;
    const ProcessResult result = runProcess({"yes"}, "", limits);
    EXPECT_EQ(result.exitCode, -1);
    EXPECT_NE(result.failure.find("more than 1 MiB"), std::string::npos) << result.failure;
}

TEST(Subprocess, AProgramThatNeverFinishesIsStopped) {
    ProcessLimits limits;
    limits.timeoutSeconds = 1;
    const ProcessResult result = runProcess({"sleep", "30"}, "", limits);
    EXPECT_EQ(result.exitCode, -1);
    EXPECT_NE(result.failure.find("longer than 1 s"), std::string::npos) << result.failure;
}

TEST(Subprocess, AMissingProgramSaysSo) {
    const ProcessResult result = runProcess({"plantfield-no-such-program"}, "");
    EXPECT_FALSE(result.started);
    EXPECT_NE(result.failure.find("plantfield-no-such-program"), std::string::npos);
    EXPECT_NE(result.failure.find("No such file"), std::string::npos) << result.failure;
}

} // namespace
} // namespace lsys
