#include "tools/lsys/check_command.h"

#include <iostream>
#include <memory>

#include "tools/lsys/plant_loading.h"

namespace tools {

Command addCheckCommand(CLI::App& app) {
    auto arguments = std::make_shared<DerivationArguments>();
    CLI::App* command = app.add_subcommand("check", "Parse a file and report every problem without deriving");
    addPlantFileOptions(*command, *arguments);
    return {command, [arguments] {
                if (!loadGrammar(*arguments)) return kBadInput;
                std::cout << arguments->file << ": ok\n";
                return 0;
            }};
}

} // namespace tools
