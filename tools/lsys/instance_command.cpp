#include "tools/lsys/instance_command.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/turtle/surfaces.h"
#include "tools/lsys/graph_options.h"
#include "tools/lsys/plant_loading.h"

namespace tools {

namespace {

struct InstanceArguments : GraphArguments {
    bool json = false;
};

const char* methodName(lsys::BGrammarMethod method) {
    switch (method) {
    case lsys::BGrammarMethod::Memoised: return "memoised";
    case lsys::BGrammarMethod::PseudoStochastic: return "pseudo-stochastic";
    case lsys::BGrammarMethod::Compressed: return "compressed";
    }
    return "";
}

int runInstance(const InstanceArguments& arguments) {
    std::optional<lsys::Grammar> grammar = loadGrammar(arguments);
    if (!grammar) return kBadInput;
    const lsys::BGrammarOptions options = instanceBGrammarOptions(arguments);
    auto start = std::chrono::steady_clock::now();
    lsys::InstanceGraphStats stats;
    lsys::BGrammarMethod method;
    try {
        const lsys::BGrammar bgrammar = lsys::buildBGrammar(*grammar, options);
        method = bgrammar.method;
        stats = lsys::instanceGraphStats(
            lsys::buildInstanceGraph(bgrammar, *grammar, graphOptions(arguments),
                                     lsys::SurfaceLibrary(lsys::meshDirectoriesFor(arguments.file))));
    } catch (const std::runtime_error& error) { // DerivationError, SurfaceError
        return failed(arguments, error);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (arguments.json) {
        nlohmann::ordered_json out;
        for (const lsys::NamedInstanceStat& stat : lsys::namedStats(stats))
            std::visit([&](auto value) { out[std::string(stat.name)] = value; }, stat.value);
        out["method"] = methodName(method);
        out["seconds"] = seconds;
        std::cout << out.dump() << '\n';
    } else {
        std::cout << stats.primitives << " primitives (" << stats.joints << " joints) in " << stats.instances
                  << " instances of " << stats.objects << " objects from " << stats.nodes << " nodes, "
                  << stats.compression() << ":1, " << stats.bytesGraph << " bytes against " << stats.bytesFlat
                  << " flat (" << methodName(method) << ", " << seconds << " s)\n";
    }
    return 0;
}

} // namespace

Command addInstanceCommand(CLI::App& app) {
    auto arguments = std::make_shared<InstanceArguments>();
    CLI::App* command = app.add_subcommand(
        "instance",
        "Build the InstanceGraph (after the Calgary b-grammar thesis: the b-grammar's shared subtrees placed by "
        "the turtle) of the plant and count "
        "it without expanding: primitives = segments + surfaces + spheres + polygons, joints = segments, nodes = "
        "b-grammar non-terminals + the axiom, objects = distinct (node, entry turtle values it reads), instances = "
        "references to objects in all objects + primitives placed directly, compression = primitives / instances, "
        "bytes_graph = the graph's memory, bytes_flat = primitives x one flat primitive record. Context-free rules are "
        "shared by (module, remaining steps); context-sensitive, cut or random ones (without --randomness) are derived "
        "and compressed (SEQUITUR). docs/INSTANCING.md");
    addDerivationOptions(*command, *arguments);
    addGraphOptions(*command, *arguments);
    command->add_flag(
        "--json", arguments->json,
        "Print {\"primitives\", \"joints\", \"nodes\", \"objects\", \"instances\", \"compression\", \"bytes_graph\", "
        "\"bytes_flat\", \"method\", \"seconds\"} as JSON");
    command->add_option("--max-nodes", arguments->limits.maxNodes, "Node budget of the graph; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    command
        ->add_option("--max-items", arguments->limits.maxItems,
                     "Budget of body entries of the graph; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    command->add_option("--max-modules", arguments->maxModules, "Module budget when the word must be derived first")
        ->check(CLI::PositiveNumber);
    return {command, [arguments] { return runInstance(*arguments); }};
}

} // namespace tools
