// runProcess and Process (lsystem/common/subprocess.h), which run the C
// preprocessor and the video encoder: input and output larger than a pipe
// holds, input written piece by piece, programs that stop reading, write
// without end or never finish, and programs that do not exist.

#include <gtest/gtest.h>

#include "lsystem/common/subprocess.h"

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

// Pieces of 1 MiB, each more than a pipe holds, while the program's output
// (as large) is drained between them.
TEST(Subprocess, InputWrittenPieceByPieceArrivesWhole) {
    Process process({"cat"});
    ASSERT_TRUE(process.started());
    std::string expected;
    for (char c : {'a', 'b', 'c'}) {
        const std::string piece(size_t(1) << 20, c);
        ASSERT_TRUE(process.write(piece));
        expected += piece;
    }
    const ProcessResult result = process.finish();
    EXPECT_EQ(result.exitCode, 0);
    EXPECT_EQ(result.out, expected);
}

TEST(Subprocess, WritingToAProgramThatExitedFailsWithoutStoppingTheCaller) {
    Process process({"sh", "-c", "echo refused >&2; exit 4"});
    ASSERT_TRUE(process.started());
    bool accepted = true;
    for (int i = 0; i < 64 && accepted; ++i) accepted = process.write(std::string(size_t(1) << 20, 'x'));
    EXPECT_FALSE(accepted);
    const ProcessResult result = process.finish();
    EXPECT_EQ(result.exitCode, 4);
    EXPECT_EQ(result.err, "refused\n");
}

// The time limit counts from the start, writes included.
TEST(Subprocess, AStreamedProgramPastItsTimeLimitIsStopped) {
    ProcessLimits limits;
    limits.timeoutSeconds = 1;
    Process process({"sh", "-c", "sleep 30"}, limits);
    EXPECT_FALSE(process.write(std::string(size_t(4) << 20, 'x')));
    const ProcessResult result = process.finish();
    EXPECT_EQ(result.exitCode, -1);
    EXPECT_NE(result.failure.find("longer than 1 s"), std::string::npos) << result.failure;
}

} // namespace
} // namespace lsys
