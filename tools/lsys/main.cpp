// lsys: derive, check, instance, export, ramify and render plant files from
// the command line. Each command is in its own file, which adds its
// subcommand and options (tools/lsys/*_command.h); here the app is set up
// (--version, --help-turtle) and the command given is run.
// Exit codes: 0 success, 2 bad input (parse errors, budget exceeded, out of memory), 1 usage errors.

#include <algorithm>
#include <iostream>
#include <new>
#include <string>

#include <CLI/CLI.hpp>
#include <plantfield_version.h>

#include "lsystem/common/file_reader.h"
#include "lsystem/turtle/turtle_commands.h"
#include "tools/crash_report.h"
#include "tools/lsys/check_command.h"
#include "tools/lsys/derive_command.h"
#include "tools/lsys/export_command.h"
#include "tools/lsys/instance_command.h"
#include "tools/lsys/plant_loading.h"
#include "tools/lsys/ramify_command.h"
#include "tools/lsys/render_command.h"

int main(int argc, char** argv) {
    tools::reportCrashes("lsys");
    CLI::App app{
        "lsys: derive, check, instance, export and render L-systems written in the .lsys notation or a dialect "
        "(docs/DIALECTS.md)"};
    app.set_version_flag("--version", std::string("lsys ") + pf::kPlantfieldVersion);
    app.require_subcommand(1);
    // Printed from the commands' definitions, so it cannot fall behind the turtle.
    app.add_flag_callback(
        "--help-turtle",
        [] {
            std::cout << lsys::turtleCommandHelp();
            throw CLI::Success();
        },
        "Print the turtle's commands (symbol, parameters, what each does) and exit");
    // In the order `lsys --help` lists them.
    const tools::Command commands[] = {tools::addDeriveCommand(app),   tools::addCheckCommand(app),
                                       tools::addInstanceCommand(app), tools::addExportCommand(app),
                                       tools::addRamifyCommand(app),   tools::addRenderCommand(app)};

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : tools::kBadInput;
    }
    // Every file the command reads, which no output may replace (tools/lsys/output_check.h).
    const lsys::ReadFileLog runInputs;
    try {
        // The app requires one command: exactly one was parsed.
        return std::ranges::find_if(commands, [](const tools::Command& command) { return command.command->parsed(); })
            ->run();
    } catch (const std::bad_alloc&) { // a stage the memory budget does not count
        std::cerr << "lsys: error: out of memory (--memory-budget, -n fewer steps or a smaller plant)\n";
        return tools::kBadInput;
    }
}
