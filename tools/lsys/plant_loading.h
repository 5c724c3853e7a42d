// Reading the plant file a deriving command starts from: the file or vlab
// object in its dialect, with -D's constants, its problems printed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lsystem/dialects/dialect.h"
#include "lsystem/grammar.h"

namespace tools {

// lsys' exit status for bad input: a file's problems, a budget exceeded.
inline constexpr int kBadInput = 2;

// Parses `file` (lsystem/vlab/object.h: a file or a vlab object folder) with
// `defines` ("NAME=VALUE" items of -D) overriding its #define constants.
// Prints warnings to stderr; on problems prints them all and returns nullopt.
std::optional<lsys::Grammar> loadGrammar(const std::string& file, const std::optional<lsys::Dialect>& dialect,
                                         const std::vector<std::string>& defines);

} // namespace tools
