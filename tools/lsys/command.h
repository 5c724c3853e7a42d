// One lsys command: the subcommand its add…Command (tools/lsys/*_command.h)
// puts on the app, and how to run it once the app has parsed it.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace tools {

struct Command {
    CLI::App* command = nullptr;
    std::function<int()> run; // once the app has parsed `command`; the exit code
};

} // namespace tools
