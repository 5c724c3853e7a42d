// lsys ramify: ramification matrices of plants, and trees generated from
// them (lsystem/ramification/, docs/RAMIFICATION.md).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace tools {

struct RamifyCommand {
    CLI::App* command = nullptr;
    std::function<int()> run; // once the app has parsed `command`; the exit code
};

// Adds the `ramify` subcommand and its options to `app`.
RamifyCommand addRamifyCommand(CLI::App& app);

} // namespace tools
