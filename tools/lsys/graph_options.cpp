#include "tools/lsys/graph_options.h"

namespace tools {

void addGraphOptions(CLI::App& command, GraphArguments& arguments) {
    command
        .add_option("--randomness", arguments.randomness,
                    "Randomness factor k (Calgary b-grammar thesis, §5.1): at most k rewrites per module and step "
                    "for random rules; the plant then differs from derive's (same statistics). 0: exact, derived and "
                    "compressed")
        ->check(CLI::Range(0, 1'000'000));
    command
        .add_option("--granularity", arguments.graphOptions.orientationGranularity,
                    "G of the Calgary b-grammar thesis, §5.3: share subtrees whose entry orientation relative to "
                    "the tropism vector falls in the same pi/G cell (approximate); 0: exact sharing only")
        ->check(CLI::Range(0, 1'000'000));
}

lsys::BGrammarOptions instanceBGrammarOptions(const GraphArguments& arguments) {
    lsys::BGrammarOptions options = bgrammarOptions(arguments);
    options.randomness = arguments.randomness;
    options.limits = arguments.limits;
    return options;
}

lsys::InstanceGraphOptions graphOptions(const GraphArguments& arguments) {
    lsys::InstanceGraphOptions options = arguments.graphOptions;
    options.memory = arguments.memory;
    return options;
}

} // namespace tools
