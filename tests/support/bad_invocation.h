// Table-driven checks that a tool rejects bad command lines clearly: exit
// code 2, "error" and a telling word in the message, and nothing written.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>

namespace pf::test {

struct BadInvocation {
    const char* name; // the ctest name suffix
    const char* args; // OUT is replaced by a path in an empty scratch folder
    const char* expectedInMessage;
};

// gtest prints parameters into ctest's test list: the name, not the bytes.
inline void PrintTo(const BadInvocation& invocation, std::ostream* os) { *os << invocation.name; }
inline std::string invocationName(const ::testing::TestParamInfo<BadInvocation>& info) { return info.param.name; }

// Runs `binary args` with OUT → `outputStem` (inside `scratch`, which must be empty).
void expectFailsClearlyWithoutWriting(const std::string& binary, const BadInvocation& invocation,
                                      const std::filesystem::path& scratch, const std::string& outputStem);

} // namespace pf::test
