// lsys derive FILE [-n STEPS] [--seed S] [-D NAME=VALUE]... [--dialect D]
//   [--print [--format text|cpfg]] [--compare STRINGFILE] [--json] [--max-modules N] [--threads N]:
// derives a plant file and reports, prints or counts the word, or compares
// it with a string file.
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `derive` subcommand and its options to `app`.
Command addDeriveCommand(CLI::App& app);

} // namespace tools
