// lsys ramify: ramification matrices of plants, and trees generated from
// them (lsystem/ramification/, docs/RAMIFICATION.md).
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `ramify` subcommand and its options to `app`.
Command addRamifyCommand(CLI::App& app);

} // namespace tools
