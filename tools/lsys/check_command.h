// lsys check FILE [-D NAME=VALUE]... [--dialect D]: parses a plant file and
// reports every problem without deriving.
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `check` subcommand and its options to `app`.
Command addCheckCommand(CLI::App& app);

} // namespace tools
