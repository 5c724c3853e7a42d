#include "bad_invocation.h"

#include "run_command.h"

namespace pf::test {

void expectFailsClearlyWithoutWriting(const std::string& binary, const BadInvocation& invocation,
                                      const std::filesystem::path& scratch, const std::string& outputStem) {
    std::string args = invocation.args;
    if (const size_t at = args.find("OUT"); at != std::string::npos)
        args.replace(at, 3, (scratch / outputStem).string());
    const CommandResult r = runCommand(binary + " " + args);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(invocation.expectedInMessage), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(scratch)) << "a failed run left files behind";
}

} // namespace pf::test
