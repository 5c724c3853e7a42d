// lsys instance FILE [-n STEPS] [--seed S] [-D NAME=VALUE]... [--dialect D]
//   [--randomness K] [--granularity G] [--json] [--max-nodes N] [--max-items N] [--max-modules N]:
// builds a plant's InstanceGraph and counts it without expanding
// (docs/INSTANCING.md).
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `instance` subcommand and its options to `app`.
Command addInstanceCommand(CLI::App& app);

} // namespace tools
