// lsys: derive, check and instance (b-grammar statistics of) .lsys files from the command line.
//   lsys derive FILE [-n STEPS] [--seed S] [-D NAME=VALUE]... [--dialect D] [--print [--format text|cpfg]] [--compare
//   STRINGFILE] [--json]
//   [--max-modules N] lsys check FILE [-D NAME=VALUE]... [--dialect D] lsys instance FILE [-n STEPS] [--seed S] [-D
//   NAME=VALUE]... [--dialect D] [--randomness K] [--json] lsys export FILE [-n STEPS] [--seed S] [-D NAME=VALUE]...
//   [--dialect D] -o OUT.gltf|.glb|.obj [--flat|--instanced]
//               [--randomness K] [--granularity G] [--max-gltf-nodes N] [--geometry drawn|frusta|tubes]
//               [--generalized-cylinders] [--sides N] [--skeleton|--no-skeleton] [--height H]
//   lsys ramify …, lsys render … (tools/lsys/ramify_command.h, tools/lsys/render_command.h)
//   lsys --help-turtle
// derive, instance and export take --memory-budget SIZE (tools/memory_budget_option.h).
// Exit codes: 0 success, 2 bad input (parse errors, budget exceeded, out of memory), 1 usage errors.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <plantfield_version.h>

#include "lsystem/common/error.h"
#include "lsystem/components/component_graph.h"
#include "lsystem/dialects/dialect.h"
#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/language/parser.h"
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"
#include "tools/lsys/plant_loading.h"
#include "tools/lsys/ramify_command.h"
#include "tools/lsys/render_command.h"

namespace {

using tools::kBadInput;
// --sides: a segment's ring needs 3 sides; past 1024 a plant's mesh is
// thousands of times its default size for no visible gain.
constexpr uint32_t kMinSides = 3, kMaxSides = 1024;

struct Arguments : tools::DerivationArguments {
    bool print = false;
    std::string printFormat = "text"; // --format: "text" or "cpfg"
    std::string compareWith;          // --compare: a string file to compare the derived string with
    bool json = false;
    int threads = 2;
    int randomness = 0;
    lsys::BGrammarLimits limits;
    lsys::InstanceGraphOptions graphOptions;
    std::string output;
    bool instanced = false; // export: the InstanceGraph's hierarchy rather than the flat plant
    lsys::ExportOptions exportOptions;
    lsys::GraphExportOptions graphExportOptions;
    std::optional<float> height; // export --height: metres the plant's meshes are scaled to
};

// Prints what went wrong with the file, and the way out of a budget.
int failed(const Arguments& arguments, const std::exception& error) {
    std::cerr << arguments.file << ": error: " << error.what();
    if (dynamic_cast<const lsys::ModuleBudgetError*>(&error))
        std::cerr << " (--max-modules sets the budget; -n derives fewer steps)";
    std::cerr << '\n';
    return kBadInput;
}

lsys::DeriveOptions deriveOptions(const Arguments& arguments) {
    lsys::DeriveOptions options;
    options.steps = arguments.steps;
    options.seed = arguments.seed;
    options.maxModules = arguments.maxModules;
    options.memory = arguments.memory;
    options.threads = arguments.threads;
    return options;
}

// --compare: the derived string against a string file (cpfg's -str output, or --print's).
int compare(const Arguments& arguments, const lsys::Grammar& grammar, const lsys::ModuleString& string) {
    std::string problem;
    const std::string text = lsys::readTextFile(arguments.compareWith, problem);
    if (!problem.empty()) {
        std::cerr << arguments.compareWith << ": error: cannot read file: it " << problem << "\n";
        return kBadInput;
    }
    if (std::optional<std::string> difference = lsys::firstDifference(string, grammar.symbols, text)) {
        std::cout << arguments.compareWith << " differs: " << *difference << "\n";
        return 1;
    }
    std::cout << arguments.compareWith << " is the same string: " << string.size()
              << " modules, parameters within 1e-4 relative\n";
    return 0;
}

int derive(const Arguments& arguments) {
    std::optional<lsys::Grammar> grammar = tools::loadGrammar(arguments);
    if (!grammar) return kBadInput;
    const lsys::DeriveOptions options = deriveOptions(arguments);
    auto start = std::chrono::steady_clock::now();
    lsys::ModuleString string;
    try {
        string = lsys::derive(*grammar, options);
    } catch (const lsys::DerivationError& error) {
        return failed(arguments, error);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int steps = options.steps.value_or(grammar->derivationLength);

    if (!arguments.compareWith.empty()) return compare(arguments, *grammar, string);
    if (arguments.print) {
        const bool cpfg = arguments.printFormat == "cpfg";
        lsys::writeText(string, grammar->symbols, cpfg ? lsys::TextLayout::Cpfg : lsys::TextLayout::OneLine,
                        [](std::string_view chunk) { std::fwrite(chunk.data(), 1, chunk.size(), stdout); });
        if (!cpfg) std::fputc('\n', stdout);
    }
    if (arguments.json) {
        nlohmann::json countsJson = nlohmann::json::object();
        for (const auto& [name, count] : lsys::moduleCounts(string, grammar->symbols)) countsJson[name] = count;
        nlohmann::json out = {
            {"modules", string.size()}, {"steps", steps}, {"counts", countsJson}, {"seconds", seconds}};
        std::cout << out.dump() << '\n';
    }
    if (!arguments.print && !arguments.json) std::cout << string.size() << " modules after " << steps << " steps\n";
    return 0;
}

const char* methodName(lsys::BGrammarMethod method) {
    switch (method) {
    case lsys::BGrammarMethod::Memoised: return "memoised";
    case lsys::BGrammarMethod::PseudoStochastic: return "pseudo-stochastic";
    case lsys::BGrammarMethod::Compressed: return "compressed";
    }
    return "";
}

// The b-grammar of the word the turtle reads, as `instance` and `export
// --instanced` build it: with --randomness and the graph's budgets.
lsys::BGrammarOptions instanceBGrammarOptions(const Arguments& arguments) {
    lsys::BGrammarOptions options = tools::bgrammarOptions(arguments);
    options.randomness = arguments.randomness;
    options.limits = arguments.limits;
    return options;
}

lsys::InstanceGraphOptions graphOptions(const Arguments& arguments) {
    lsys::InstanceGraphOptions options = arguments.graphOptions;
    options.memory = arguments.memory;
    return options;
}

int instance(const Arguments& arguments) {
    std::optional<lsys::Grammar> grammar = tools::loadGrammar(arguments);
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

// The box of the flattened graph's meshes as the flat form bakes them.
lsys::Bounds flatBounds(const lsys::PlantAsset& plant, const lsys::GraphExportOptions& options) {
    if (options.geometry == lsys::ExportGeometry::Turtle)
        return lsys::bakedBounds(plant, options.segments, options.detail);
    const lsys::DrawnOptions drawn = lsys::exportedDrawnOptions(options.detail.segmentSides);
    lsys::Bounds bounds;
    for (const lsys::TriangleMesh& mesh : lsys::drawnMeshesByMaterial(plant, lsys::drawnScaleOf(plant), drawn))
        for (const glm::vec3& p : mesh.positions) bounds.extend(p);
    return bounds;
}

// The scale that makes the flattened graph's meshes --height tall, or
// nullopt (after saying why) for a plant without height.
std::optional<float> exportScale(const Arguments& arguments, const lsys::PlantAsset& plant,
                                 const lsys::GraphExportOptions& options) {
    const float scale = lsys::heightScale(flatBounds(plant, options), *arguments.height);
    if (scale > 0.0f && std::isfinite(scale)) return scale;
    std::cerr << arguments.file << ": error: --height: the plant has no height to scale (its meshes' y extent is 0)\n";
    return std::nullopt;
}

// ", 10 m tall (scaled by 0.5)" for --height, else nothing: the summary's end.
std::string scaleNote(const Arguments& arguments, float scale) {
    if (!arguments.height) return "";
    std::ostringstream note;
    note << ", " << *arguments.height << " m tall (scaled by " << scale << ")";
    return note.str();
}

// The plant the graph stands for, flattened within the module and memory
// budgets, for --height: the flat form's meshes are the instanced form's
// placed (bark tubes and generalised cylinders aside, whose chains the instanced form ends
// at each instance), so both forms are scaled to the same height. The
// graph's own boxes would not do: each instance adds its object's rotated
// box's box (data/plants/fractal_bush.lsys: 12 % too tall).
lsys::PlantAsset flatPlant(const Arguments& arguments, const lsys::InstanceGraph& graph,
                           const lsys::SurfaceLibrary& surfaces) {
    const lsys::InstanceGraphStats stats = lsys::instanceGraphStats(graph);
    lsys::need(arguments.memory, "flatten",
               lsys::bytesPlus(lsys::bytesTimes(stats.primitives, sizeof(lsys::Primitive)),
                               lsys::bytesTimes(stats.joints, sizeof(lsys::Joint))));
    return lsys::flatten(graph, surfaces, arguments.maxModules);
}

// The InstanceGraph written with its hierarchy (glTF only; OBJ is always flat).
int exportGraph(const Arguments& arguments, const lsys::Grammar& grammar) {
    const auto start = std::chrono::steady_clock::now();
    const lsys::SurfaceLibrary surfaces(lsys::meshDirectoriesFor(arguments.file));
    lsys::InstanceGraph graph;
    try {
        graph = lsys::buildInstanceGraph(lsys::buildBGrammar(grammar, instanceBGrammarOptions(arguments)), grammar,
                                         graphOptions(arguments), surfaces);
    } catch (const std::runtime_error& error) { // DerivationError, SurfaceError
        return failed(arguments, error);
    }
    std::optional<float> scale = 1.0f;
    try {
        if (arguments.height)
            scale = exportScale(arguments, flatPlant(arguments, graph, surfaces), arguments.graphExportOptions);
    } catch (const std::runtime_error& error) { // DerivationError, MemoryBudgetError
        return failed(arguments, error);
    }
    if (!scale) return kBadInput;
    lsys::GraphExportSummary summary;
    try {
        lsys::GraphExportOptions options = arguments.graphExportOptions;
        options.memory = arguments.memory;
        options.scale = *scale;
        summary = lsys::exportInstanceGraph(graph, surfaces, arguments.output, options);
    } catch (const std::runtime_error& error) {
        std::cerr << "lsys: error: " << error.what() << '\n';
        return kBadInput;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const lsys::InstanceGraphStats stats = lsys::instanceGraphStats(graph);
    std::cerr << arguments.output << ": " << stats.primitives << " primitives in " << stats.objects << " objects, "
              << summary.meshes << " meshes, " << summary.nodes << " nodes" << scaleNote(arguments, *scale) << " ("
              << seconds << " s)\n";
    return 0;
}

// The tree of a .ram.json file, --seed replacing the file's.
std::optional<lsys::PlantAsset> generatedTree(const Arguments& arguments) {
    lsys::RamificationFile file = lsys::readRamificationFile(arguments.file);
    if (!file.tree) {
        std::cerr << lsys::formatDiagnostics(file.diagnostics, file.source);
        return std::nullopt;
    }
    if (arguments.seed) file.tree->seed = *arguments.seed;
    return lsys::plantOf(lsys::generateTree(*file.tree), arguments.memory);
}

// Derives, interprets (surfaces from data/meshes near the file) and writes
// the plant; a .comp.json file is built from its components and a .ram.json
// tree generated from its matrix instead.
int exportCommand(const Arguments& arguments) {
    const bool components = lsys::components::isComponentFile(arguments.file);
    const bool ramified = lsys::isRamificationFile(arguments.file);
    if ((components || ramified) && arguments.instanced) {
        std::cerr << "lsys: error: --instanced needs an L-system (a component plant or ramification tree has no "
                     "b-grammar)\n";
        return 1;
    }
    if ((components || ramified) && (arguments.steps || !arguments.defines.empty() || arguments.dialect)) {
        std::cerr << "lsys: error: -n, -D and --dialect derive an L-system; a "
                  << (components ? "component plant" : "ramification tree")
                  << " is built, not derived (--seed replaces its file's seed)\n";
        return 1;
    }
    std::optional<lsys::Grammar> grammar;
    if (!components && !ramified) {
        grammar = tools::loadGrammar(arguments);
        if (!grammar) return kBadInput;
        if (arguments.instanced) return exportGraph(arguments, *grammar);
    }
    auto start = std::chrono::steady_clock::now();
    lsys::PlantAsset plant;
    try {
        if (components) {
            lsys::components::ComponentGraph graph = lsys::components::readComponentGraph(arguments.file);
            if (arguments.seed) graph.seed = *arguments.seed;
            plant = lsys::components::buildComponentPlant(graph, arguments.memory);
        } else if (ramified) {
            std::optional<lsys::PlantAsset> tree = generatedTree(arguments);
            if (!tree) return kBadInput;
            plant = std::move(*tree);
        } else {
            const lsys::ModuleString string = lsys::derive(*grammar, deriveOptions(arguments));
            plant = lsys::plantFromGrammar(
                *grammar, string, lsys::SurfaceLibrary(lsys::meshDirectoriesFor(arguments.file)), arguments.memory);
        }
    } catch (const lsys::components::ComponentError& error) { // located in the file already
        std::cerr << "lsys: error: " << error.what() << '\n';
        return kBadInput;
    } catch (const std::runtime_error& error) { // DerivationError, SurfaceError
        return failed(arguments, error);
    }
    float scale = 1.0f;
    try {
        lsys::ExportOptions options = arguments.exportOptions;
        options.memory = arguments.memory;
        options.height = arguments.height.value_or(0.0f);
        scale = lsys::exportPlant(plant, arguments.output, options);
    } catch (const std::runtime_error& error) {
        std::cerr << "lsys: error: " << error.what() << '\n';
        return kBadInput;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << arguments.output << ": " << plant.primitives.size() << " primitives, " << plant.joints.size()
              << " joints" << scaleNote(arguments, scale) << " (" << seconds << " s)\n";
    return 0;
}

// --randomness and --granularity: how the InstanceGraph is built.
void addGraphOptions(CLI::App& command, Arguments& arguments) {
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

// The meshes --geometry names (docs/EXPORT.md): the plant as the field
// draws it, or the turtle's segments as frusta or generalised cylinders.
void setGeometry(Arguments& arguments, const std::string& name) {
    const bool drawn = name == "drawn", tubes = name == "tubes";
    arguments.exportOptions.geometry = drawn ? lsys::ExportGeometry::Drawn : lsys::ExportGeometry::Turtle;
    arguments.graphExportOptions.geometry = arguments.exportOptions.geometry;
    const lsys::SegmentGeometry segments =
        tubes ? lsys::SegmentGeometry::GeneralizedCylinders : lsys::SegmentGeometry::Frusta;
    arguments.exportOptions.segments = segments;
    arguments.graphExportOptions.segments = segments;
}

// --geometry and its older spelling --generalized-cylinders (--geometry tubes).
void addGeometryOptions(CLI::App& command, Arguments& arguments) {
    command
        .add_option_function<std::string>(
            "--geometry", [&arguments](const std::string& name) { setGeometry(arguments, name); },
            "Meshes, flat and --instanced: drawn (default: the plant as plantfield draws it up close, bark "
            "tubes, foliage ribbons, leaf outlines), frusta (the turtle's segments, one cone frustum each) or "
            "tubes (the turtle's segments as generalised cylinders)")
        ->check(CLI::IsMember({"drawn", "frusta", "tubes"}))
        ->type_name("drawn|frusta|tubes");
    command.add_flag_callback(
        "--generalized-cylinders", [&arguments] { setGeometry(arguments, "tubes"); }, "The same as --geometry tubes");
}

// --sides, --skeleton/--no-skeleton and --height: the exported plant as drawn.
void addDrawnFormOptions(CLI::App& command, Arguments& arguments) {
    command
        .add_option_function<uint32_t>(
            "--sides",
            [&arguments](uint32_t sides) {
                arguments.exportOptions.detail.segmentSides = sides;
                arguments.graphExportOptions.detail.segmentSides = sides;
            },
            "Sides of each segment's ring, flat and --instanced (default 8); with --geometry drawn the trunk's, "
            "thinner bark getting fewer (3/4, 1/2, at least 3) as plantfield draws it")
        ->check(CLI::Range(kMinSides, kMaxSides));
    command.add_flag("--skeleton,!--no-skeleton", arguments.exportOptions.skeleton,
                     "Write the joints as empty glTF nodes joint_<i> nested as the plant's skeleton (the default); "
                     "--no-skeleton writes the meshes alone. Flat glTF only: OBJ and --instanced have no skeleton");
    command
        .add_option("--height", arguments.height,
                    "Scale the plant uniformly about its base so that its meshes are H metres tall (their y extent "
                    "as written, with --geometry and --sides; --instanced: the same plant's)")
        ->check([](const std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value <= 0.0 ||
                value > std::numeric_limits<float>::max())
                return "'" + text + "' is not a height in metres above 0";
            return {};
        })
        ->type_name("H");
}

int check(const Arguments& arguments) {
    if (!tools::loadGrammar(arguments)) return kBadInput;
    std::cout << arguments.file << ": ok\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
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
    Arguments arguments;

    CLI::App* deriveCommand = app.add_subcommand("derive", "Derive an L-system and report, print or count the result");
    tools::addDerivationOptions(*deriveCommand, arguments);
    deriveCommand->add_flag("--print", arguments.print, "Print the final string, e.g. F(1,0.5)[+A(2)]");
    deriveCommand
        ->add_option("--format", arguments.printFormat,
                     "How --print writes the string: text (on one line) or cpfg (as cpfg's -str writes it: a line "
                     "break before a module once 70 characters are on the line)")
        ->check(CLI::IsMember({"text", "cpfg"}));
    deriveCommand->add_option("--compare", arguments.compareWith,
                              "Compare the derived string with a string file (cpfg's -str output, or --print's): "
                              "module for module, parameters within 1e-4 relative; exit status 1 when they differ");
    deriveCommand->add_flag("--json", arguments.json,
                            "Print {\"modules\", \"steps\", \"counts\", \"seconds\"} as JSON");
    deriveCommand->add_option("--max-modules", arguments.maxModules, "Module budget; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    deriveCommand->add_option("--threads", arguments.threads, "Rewriting threads")->check(CLI::Range(1, 64));

    CLI::App* checkCommand = app.add_subcommand("check", "Parse a file and report every problem without deriving");
    tools::addPlantFileOptions(*checkCommand, arguments);

    CLI::App* instanceCommand = app.add_subcommand(
        "instance",
        "Build the InstanceGraph (after the Calgary b-grammar thesis: the b-grammar's shared subtrees placed by "
        "the turtle) of the plant and count "
        "it without expanding: primitives = segments + surfaces + spheres + polygons, joints = segments, nodes = "
        "b-grammar non-terminals + the axiom, objects = distinct (node, entry turtle values it reads), instances = "
        "references to objects in all objects + primitives placed directly, compression = primitives / instances, "
        "bytes_graph = the graph's memory, bytes_flat = primitives x one flat primitive record. Context-free rules are "
        "shared by (module, remaining steps); context-sensitive, cut or random ones (without --randomness) are derived "
        "and compressed (SEQUITUR). docs/INSTANCING.md");
    tools::addDerivationOptions(*instanceCommand, arguments);
    addGraphOptions(*instanceCommand, arguments);
    instanceCommand->add_flag(
        "--json", arguments.json,
        "Print {\"primitives\", \"joints\", \"nodes\", \"objects\", \"instances\", \"compression\", \"bytes_graph\", "
        "\"bytes_flat\", \"method\", \"seconds\"} as JSON");
    instanceCommand
        ->add_option("--max-nodes", arguments.limits.maxNodes, "Node budget of the graph; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    instanceCommand
        ->add_option("--max-items", arguments.limits.maxItems,
                     "Budget of body entries of the graph; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    instanceCommand
        ->add_option("--max-modules", arguments.maxModules, "Module budget when the word must be derived first")
        ->check(CLI::PositiveNumber);

    CLI::App* exportSubcommand = app.add_subcommand(
        "export",
        "Derive and interpret an L-system, build a component plant (FILE.comp.json, docs/COMPONENTS.md) or generate "
        "a ramification tree (FILE.ram.json, --seed replacing its 'seed'; docs/RAMIFICATION.md), and write the plant "
        "as glTF 2.0 (.gltf, .glb) or OBJ (docs/EXPORT.md)");
    tools::addDerivationOptions(*exportSubcommand, arguments);
    exportSubcommand->add_option("-o,--output", arguments.output, "Output file: .gltf, .glb or .obj")->required();
    exportSubcommand->add_flag_callback(
        "--flat", [&arguments] { arguments.instanced = false; },
        "One mesh per material with every primitive baked in (default)");
    exportSubcommand->add_flag_callback(
        "--instanced", [&arguments] { arguments.instanced = true; },
        "Keep the InstanceGraph's hierarchy: one mesh per object shared by all its instances, one node per instance "
        "(glTF only)");
    addGraphOptions(*exportSubcommand, arguments);
    exportSubcommand
        ->add_option("--max-gltf-nodes", arguments.graphExportOptions.maxNodes,
                     "With --instanced: node budget (one node per instance path); exceeding it is an error")
        ->check(CLI::PositiveNumber);
    addGeometryOptions(*exportSubcommand, arguments);
    exportSubcommand->add_option("--max-modules", arguments.maxModules, "Module budget; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    addDrawnFormOptions(*exportSubcommand, arguments);

    const tools::RamifyCommand ramify = tools::addRamifyCommand(app);
    const tools::RenderCommand render = tools::addRenderCommand(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : kBadInput;
    }
    try {
        if (deriveCommand->parsed()) return derive(arguments);
        if (instanceCommand->parsed()) return instance(arguments);
        if (exportSubcommand->parsed()) return exportCommand(arguments);
        if (ramify.command->parsed()) return ramify.run();
        if (render.command->parsed()) return render.run();
        return check(arguments);
    } catch (const std::bad_alloc&) { // a stage the memory budget does not count
        std::cerr << "lsys: error: out of memory (--memory-budget, -n fewer steps or a smaller plant)\n";
        return kBadInput;
    }
}
