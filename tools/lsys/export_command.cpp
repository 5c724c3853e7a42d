#include "tools/lsys/export_command.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/components/component_graph.h"
#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "tools/lsys/graph_options.h"
#include "tools/lsys/output_check.h"
#include "tools/lsys/plant_loading.h"

namespace tools {

namespace {

// --sides: a segment's ring needs 3 sides; past 1024 a plant's mesh is
// thousands of times its default size for no visible gain.
constexpr uint32_t kMinSides = 3, kMaxSides = 1024;

struct ExportArguments : GraphArguments {
    std::string output;
    bool instanced = false; // the InstanceGraph's hierarchy rather than the flat plant
    lsys::ExportOptions exportOptions;
    lsys::GraphExportOptions graphExportOptions;
    std::optional<float> height; // --height: metres the plant's meshes are scaled to
};

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
std::optional<float> exportScale(const ExportArguments& arguments, const lsys::PlantAsset& plant,
                                 const lsys::GraphExportOptions& options) {
    const float scale = lsys::heightScale(flatBounds(plant, options), *arguments.height);
    if (scale > 0.0f && std::isfinite(scale)) return scale;
    std::cerr << arguments.file << ": error: --height: the plant has no height to scale (its meshes' y extent is 0)\n";
    return std::nullopt;
}

// ", 10 m tall (scaled by 0.5)" for --height, else nothing: the summary's end.
std::string scaleNote(const ExportArguments& arguments, float scale) {
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
lsys::PlantAsset flatPlant(const ExportArguments& arguments, const lsys::InstanceGraph& graph,
                           const lsys::SurfaceLibrary& surfaces) {
    const lsys::InstanceGraphStats stats = lsys::instanceGraphStats(graph);
    lsys::need(arguments.memory, "flatten",
               lsys::bytesPlus(lsys::bytesTimes(stats.primitives, sizeof(lsys::Primitive)),
                               lsys::bytesTimes(stats.joints, sizeof(lsys::Joint))));
    return lsys::flatten(graph, surfaces, arguments.maxModules);
}

// The InstanceGraph written with its hierarchy (glTF only; OBJ is always flat).
int exportGraph(const ExportArguments& arguments, const lsys::Grammar& grammar) {
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
std::optional<lsys::PlantAsset> generatedTree(const ExportArguments& arguments) {
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
int runExport(const ExportArguments& arguments) {
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
    const std::vector<std::filesystem::path> outputs = lsys::exportedFiles(arguments.output);
    if (outputRefused(outputs, arguments.file)) return kBadInput;
    std::optional<lsys::Grammar> grammar;
    if (!components && !ramified) {
        grammar = loadGrammar(arguments);
        // Again now that its includes and a vlab object's files are read.
        if (!grammar || outputRefused(outputs, arguments.file)) return kBadInput;
        if (arguments.instanced) return exportGraph(arguments, *grammar);
    }
    auto start = std::chrono::steady_clock::now();
    lsys::PlantAsset plant;
    try {
        if (components) {
            lsys::components::ComponentGraph graph = lsys::components::readComponentGraph(arguments.file);
            if (outputRefused(outputs, arguments.file)) return kBadInput; // its component files read
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

// The meshes --geometry names (docs/EXPORT.md): the plant as the field
// draws it, or the turtle's segments as frusta or generalised cylinders.
void setGeometry(ExportArguments& arguments, const std::string& name) {
    const bool drawn = name == "drawn", tubes = name == "tubes";
    arguments.exportOptions.geometry = drawn ? lsys::ExportGeometry::Drawn : lsys::ExportGeometry::Turtle;
    arguments.graphExportOptions.geometry = arguments.exportOptions.geometry;
    const lsys::SegmentGeometry segments =
        tubes ? lsys::SegmentGeometry::GeneralizedCylinders : lsys::SegmentGeometry::Frusta;
    arguments.exportOptions.segments = segments;
    arguments.graphExportOptions.segments = segments;
}

// --geometry and its older spelling --generalized-cylinders (--geometry tubes).
void addGeometryOptions(CLI::App& command, ExportArguments& arguments) {
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
void addDrawnFormOptions(CLI::App& command, ExportArguments& arguments) {
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

} // namespace

Command addExportCommand(CLI::App& app) {
    auto arguments = std::make_shared<ExportArguments>();
    CLI::App* command = app.add_subcommand(
        "export",
        "Derive and interpret an L-system, build a component plant (FILE.comp.json, docs/COMPONENTS.md) or generate "
        "a ramification tree (FILE.ram.json, --seed replacing its 'seed'; docs/RAMIFICATION.md), and write the plant "
        "as glTF 2.0 (.gltf, .glb) or OBJ (docs/EXPORT.md)");
    addDerivationOptions(*command, *arguments);
    command->add_option("-o,--output", arguments->output, "Output file: .gltf, .glb or .obj")->required();
    command->add_flag_callback(
        "--flat", [arguments] { arguments->instanced = false; },
        "One mesh per material with every primitive baked in (default)");
    command->add_flag_callback(
        "--instanced", [arguments] { arguments->instanced = true; },
        "Keep the InstanceGraph's hierarchy: one mesh per object shared by all its instances, one node per instance "
        "(glTF only)");
    addGraphOptions(*command, *arguments);
    command
        ->add_option("--max-gltf-nodes", arguments->graphExportOptions.maxNodes,
                     "With --instanced: node budget (one node per instance path); exceeding it is an error")
        ->check(CLI::PositiveNumber);
    addGeometryOptions(*command, *arguments);
    command->add_option("--max-modules", arguments->maxModules, "Module budget; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    addDrawnFormOptions(*command, *arguments);
    return {command, [arguments] { return runExport(*arguments); }};
}

} // namespace tools
