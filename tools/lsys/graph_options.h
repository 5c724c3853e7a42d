// The InstanceGraph that lsys instance and export --instanced build:
// --randomness and --granularity on their command lines, and the b-grammar
// and graph options they give.
#pragma once

#include <CLI/CLI.hpp>

#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "tools/lsys/plant_loading.h"

namespace tools {

struct GraphArguments : DerivationArguments {
    int randomness = 0;
    lsys::BGrammarLimits limits;
    lsys::InstanceGraphOptions graphOptions;
};

// --randomness and --granularity: how the InstanceGraph is built.
void addGraphOptions(CLI::App& command, GraphArguments& arguments);

// The b-grammar of the word the turtle reads, with --randomness and the graph's budgets.
lsys::BGrammarOptions instanceBGrammarOptions(const GraphArguments& arguments);

// The graph's options within --memory-budget.
lsys::InstanceGraphOptions graphOptions(const GraphArguments& arguments);

} // namespace tools
