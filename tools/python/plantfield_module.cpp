// The Python module `plantfield` (docs/PYTHON.md): load or parse a plant in
// any dialect, derive it, read its instance-graph statistics, its
// ramification matrix (Tankard 2001, §2.2) and export it, generate trees
// from ramification files,
// as the lsys tool does (tools/lsys/*_command.cpp), with diagnostics raised as
// plantfield.LsystemError; and render scenes headless (render_bindings.h).

#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <plantfield_version.h>

#include "arguments.h"
#include "render_bindings.h"

#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/dialects/dialect.h"
#include "lsystem/export/graph_export.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/language/parser.h"
#include "lsystem/ramification/ramification.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/ramification/ramification_generate.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

namespace py = pybind11;

namespace {

// A parsed plant with what the module needs besides the grammar: where it
// was read from (meshes are found near it) and its warnings.
struct PyGrammar {
    lsys::Grammar grammar;
    std::string file;   // the path, or the name parse() was given
    std::string source; // the text formatDiagnostics quotes
    std::vector<lsys::Diagnostic> warnings;
    bool fromFile = false;
};

struct PyDerived {
    lsys::ModuleString string;
    std::shared_ptr<PyGrammar> grammar; // its symbol table
};

// Set in PYBIND11_MODULE: plantfield.LsystemError (raised by hand, never
// translated from C++, so its C++ type is only a tag).
struct LsystemErrorTag {};
py::handle lsystemError; // the module's attribute holds the reference

py::list diagnosticTuples(const std::vector<lsys::Diagnostic>& diagnostics) {
    py::list out;
    for (const lsys::Diagnostic& d : diagnostics) {
        std::string message = d.message;
        if (!d.expected.empty()) message += " (expected " + d.expected + ")";
        out.append(py::make_tuple(d.file, d.line, d.column, message));
    }
    return out;
}

// Raises LsystemError with every diagnostic, or returns the grammar.
std::shared_ptr<PyGrammar> finish(lsys::ParseResult& result, std::string file, std::string source, bool fromFile) {
    if (!result.ok()) {
        py::object error = lsystemError(lsys::formatDiagnostics(result.diagnostics, source));
        error.attr("diagnostics") = diagnosticTuples(result.diagnostics);
        PyErr_SetObject(lsystemError.ptr(), error.ptr());
        throw py::error_already_set();
    }
    auto grammar = std::make_shared<PyGrammar>();
    grammar->grammar = std::move(result.grammar);
    grammar->file = std::move(file);
    grammar->source = std::move(source);
    grammar->warnings = std::move(result.warnings);
    grammar->fromFile = fromFile;
    return grammar;
}

std::optional<lsys::Dialect> dialectArgument(const std::optional<std::string>& name) {
    if (!name) return std::nullopt;
    std::optional<lsys::Dialect> dialect = lsys::dialectFromName(*name);
    if (!dialect) throw py::value_error("unknown dialect '" + *name + "' (expected " + lsys::knownDialects() + ")");
    return dialect;
}

std::shared_ptr<PyGrammar> load(const std::filesystem::path& path,
                                const std::unordered_map<std::string, double>& defines,
                                const std::optional<std::string>& dialect) {
    pyargs::checkDefines(defines);
    lsys::ParseOptions options;
    options.file = path.string();
    options.defines = defines;
    const std::optional<lsys::Dialect> given = dialectArgument(dialect);
    lsys::vlab::PlantFile plant;
    {
        py::gil_scoped_release release;
        const pyargs::SessionReads read;
        plant = lsys::vlab::loadPlant(path, given, options);
    }
    return finish(plant.parsed, path.string(), std::move(plant.source), true);
}

std::shared_ptr<PyGrammar> parse(const std::string& text, const std::string& file,
                                 const std::unordered_map<std::string, double>& defines,
                                 const std::optional<std::string>& dialect) {
    pyargs::checkDefines(defines);
    lsys::ParseOptions options;
    options.file = file;
    options.defines = defines;
    lsys::ParseResult result = lsys::parseDialect(dialectArgument(dialect), text, options);
    return finish(result, file, text, false);
}

// Meshes are looked for near a plant read from a file, as lsys does.
lsys::SurfaceLibrary surfacesFor(const PyGrammar& grammar) {
    return grammar.fromFile ? lsys::SurfaceLibrary(lsys::meshDirectoriesFor(grammar.file)) : lsys::SurfaceLibrary();
}

// Every plant argument: a None or a number instead is a TypeError, not a null pointer.
std::shared_ptr<PyGrammar> grammarArgument(const py::object& grammar) {
    return pyargs::objectArgument<PyGrammar>(grammar, "grammar", "a plantfield.Grammar (load, parse or ramified_tree)");
}

lsys::DeriveOptions deriveOptions(std::optional<int> steps, std::optional<uint64_t> seed, size_t maxModules) {
    pyargs::checkSteps(steps);
    lsys::DeriveOptions options;
    options.steps = steps;
    options.seed = seed;
    options.maxModules = maxModules;
    return options;
}

lsys::BGrammarOptions bgrammarOptions(std::optional<int> steps, std::optional<uint64_t> seed, size_t maxModules) {
    pyargs::checkSteps(steps);
    lsys::BGrammarOptions options;
    options.steps = steps;
    options.seed = seed;
    options.interpreted = true; // the word the turtle reads
    options.maxModules = maxModules;
    return options;
}

PyDerived derive(const py::object& grammarObject, std::optional<int> steps, std::optional<uint64_t> seed,
                 size_t maxModules) {
    std::shared_ptr<PyGrammar> grammar = grammarArgument(grammarObject);
    const lsys::DeriveOptions options = deriveOptions(steps, seed, maxModules);
    PyDerived out;
    {
        py::gil_scoped_release release;
        out.string = lsys::derive(grammar->grammar, options);
    }
    out.grammar = std::move(grammar);
    return out;
}

py::dict counts(const PyDerived& derived) {
    py::dict out;
    for (const auto& [name, n] : lsys::moduleCounts(derived.string, derived.grammar->grammar.symbols))
        out[py::str(name)] = n;
    return out;
}

py::dict instanceStats(const py::object& grammarObject, std::optional<int> steps, std::optional<uint64_t> seed,
                       size_t maxModules) {
    const PyGrammar& grammar = *grammarArgument(grammarObject);
    const lsys::BGrammarOptions options = bgrammarOptions(steps, seed, maxModules);
    lsys::InstanceGraphStats stats;
    {
        py::gil_scoped_release release;
        const pyargs::SessionReads read; // its meshes
        const lsys::BGrammar bgrammar = lsys::buildBGrammar(grammar.grammar, options);
        stats = lsys::instanceGraphStats(lsys::buildInstanceGraph(bgrammar, grammar.grammar, {}, surfacesFor(grammar)));
    }
    py::dict out;
    for (const lsys::NamedInstanceStat& stat : lsys::namedStats(stats))
        std::visit([&](auto value) { out[py::str(std::string(stat.name))] = value; }, stat.value);
    return out;
}

void exportPlant(const py::object& grammarObject, const std::filesystem::path& path, std::optional<int> steps,
                 std::optional<uint64_t> seed, bool instanced, uint32_t sides, bool skeleton, size_t maxModules,
                 const std::string& geometry) {
    const PyGrammar& grammar = *grammarArgument(grammarObject);
    pyargs::checkSteps(steps);
    for (const std::filesystem::path& file : lsys::exportedFiles(path)) pyargs::checkOutput(file, "path");
    if (sides < 3 || sides > 1024) throw py::value_error("sides must be between 3 and 1024");
    if (geometry != "drawn" && geometry != "frusta" && geometry != "tubes")
        throw py::value_error("geometry must be 'drawn', 'frusta' or 'tubes', not '" + geometry + "'");
    // As lsys export --geometry.
    const lsys::ExportGeometry form = geometry == "drawn" ? lsys::ExportGeometry::Drawn : lsys::ExportGeometry::Turtle;
    const lsys::SegmentGeometry segments =
        geometry == "tubes" ? lsys::SegmentGeometry::GeneralizedCylinders : lsys::SegmentGeometry::Frusta;
    py::gil_scoped_release release;
    const pyargs::SessionReads read; // its meshes, which the files opened are checked against too
    const lsys::SurfaceLibrary surfaces = surfacesFor(grammar);
    if (instanced) {
        const lsys::InstanceGraph graph =
            lsys::buildInstanceGraph(lsys::buildBGrammar(grammar.grammar, bgrammarOptions(steps, seed, maxModules)),
                                     grammar.grammar, {}, surfaces);
        lsys::GraphExportOptions options;
        options.geometry = form;
        options.segments = segments;
        options.detail.segmentSides = sides;
        lsys::exportInstanceGraph(graph, surfaces, path, options);
        return;
    }
    const lsys::ModuleString string = lsys::derive(grammar.grammar, deriveOptions(steps, seed, maxModules));
    const lsys::PlantAsset plant = lsys::plantFromGrammar(grammar.grammar, string, surfaces);
    lsys::ExportOptions options;
    options.geometry = form;
    options.segments = segments;
    options.detail.segmentSides = sides;
    options.skeleton = skeleton;
    lsys::exportPlant(plant, path, options);
}

// As `lsys ramify --json` prints it for a plant: {"orders": K, "a": [...], "p": [[...], ...]}.
py::dict ramify(const py::object& grammarObject, std::optional<int> steps, std::optional<uint64_t> seed,
                size_t maxModules) {
    const PyGrammar& grammar = *grammarArgument(grammarObject);
    const lsys::DeriveOptions options = deriveOptions(steps, seed, maxModules);
    lsys::CompiledRamification compiled;
    {
        py::gil_scoped_release release;
        const pyargs::SessionReads read; // its meshes
        const lsys::ModuleString string = lsys::derive(grammar.grammar, options);
        compiled = lsys::compileRamification(lsys::plantFromGrammar(grammar.grammar, string, surfacesFor(grammar)));
    }
    const lsys::RamificationMatrix matrix = lsys::ramificationMatrix(compiled.counts);
    py::dict out;
    out["orders"] = matrix.orders();
    out["a"] = compiled.counts.a;
    out["p"] = matrix.p;
    return out;
}

// The tree a .ram.json file generates, as the plant `lsys ramify FILE -o
// tree.lsys` writes: a Grammar like any loaded one.
std::shared_ptr<PyGrammar> ramifiedTree(const std::filesystem::path& path, std::optional<uint64_t> seed,
                                        std::optional<uint64_t> maxBranches) {
    if (maxBranches && (*maxBranches < 1 || *maxBranches > lsys::kMaxRamificationBranches))
        throw py::value_error("max_branches must be 1 to " + std::to_string(lsys::kMaxRamificationBranches));
    lsys::RamificationFile file = [&path] {
        const pyargs::SessionReads read;
        return lsys::readRamificationFile(path);
    }();
    if (!file.tree) {
        lsys::ParseResult failed;
        failed.diagnostics = std::move(file.diagnostics);
        finish(failed, path.string(), std::move(file.source), true); // raises LsystemError
    }
    if (seed) file.tree->seed = *seed;
    if (maxBranches) file.tree->maxBranches = *maxBranches;
    std::string text;
    {
        py::gil_scoped_release release;
        text = lsys::lsystemText(lsys::generateTree(*file.tree),
                                 "Generated from " + path.string() + ", seed " + std::to_string(file.tree->seed));
    }
    return parse(text, path.string(), {}, std::nullopt);
}

const size_t kMaxModules = lsys::DeriveOptions{}.maxModules; // the library's default, as lsys's

} // namespace

PYBIND11_MODULE(plantfield, m) {
    m.doc() = "L-system plants of the plantfield project: load, derive, instance-graph statistics, export; "
              "frames of scenes rendered headless";
    m.attr("__version__") = pf::kPlantfieldVersion;

    // Exceptions: parse errors carry their diagnostics; derivation errors the
    // C++ message. ModuleBudgetError and MemoryBudgetError are DerivationErrors.
    lsystemError = py::exception<LsystemErrorTag>(m, "LsystemError", PyExc_ValueError).ptr();
    static py::exception<lsys::DerivationError> derivationError(m, "DerivationError", PyExc_RuntimeError);
    static py::exception<lsys::ModuleBudgetError> moduleBudgetError(m, "ModuleBudgetError", derivationError.ptr());
    static py::exception<lsys::MemoryBudgetError> memoryBudgetError(m, "MemoryBudgetError", derivationError.ptr());
    static py::exception<lsys::RamificationBudgetError> ramificationBudgetError(m, "RamificationBudgetError",
                                                                                derivationError.ptr());
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const lsys::ModuleBudgetError& e) {
            moduleBudgetError(e.what());
        } catch (const lsys::MemoryBudgetError& e) {
            memoryBudgetError(e.what());
        } catch (const lsys::RamificationBudgetError& e) {
            ramificationBudgetError(e.what());
        } catch (const lsys::DerivationError& e) {
            derivationError(e.what());
        }
    });

    py::class_<PyGrammar, std::shared_ptr<PyGrammar>>(m, "Grammar", "A parsed plant (load or parse)")
        .def_readonly("file", &PyGrammar::file)
        .def_property_readonly(
            "warnings", [](const PyGrammar& g) { return diagnosticTuples(g.warnings); },
            "Warnings as (file, line, column, message) tuples")
        .def_property_readonly("derivation_length", [](const PyGrammar& g) { return g.grammar.derivationLength; })
        .def("__repr__", [](const PyGrammar& g) { return "<plantfield.Grammar '" + g.file + "'>"; });

    py::class_<PyDerived>(m, "DerivedString", "A derived module string")
        .def("__len__", [](const PyDerived& d) { return d.string.size(); })
        .def("__str__", [](const PyDerived& d) { return lsys::toString(d.string, d.grammar->grammar.symbols); })
        .def("__repr__",
             [](const PyDerived& d) {
                 return "<plantfield.DerivedString of " + std::to_string(d.string.size()) + " modules>";
             })
        .def("counts", &counts, "Module name -> how many times it occurs")
        .def(
            "to_cpfg", [](const PyDerived& d) { return lsys::toCpfgString(d.string, d.grammar->grammar.symbols); },
            "The string as cpfg writes it (its -str output)");

    pyargs::defChecked(m, "load", &load, py::arg("path"),
                       py::arg("defines") = std::unordered_map<std::string, double>{}, py::arg("dialect") = py::none(),
                       "Reads a plant file (any dialect: its 'dialect:' line, else cpfg for .l, else native) or a vlab "
                       "object folder; raises LsystemError with every diagnostic");
    pyargs::defChecked(m, "parse", &parse, py::arg("text"), py::arg("file") = "<string>",
                       py::arg("defines") = std::unordered_map<std::string, double>{}, py::arg("dialect") = py::none(),
                       "Parses plant text; raises LsystemError with every diagnostic");
    pyargs::defChecked(
        m, "derive", &derive, py::arg("grammar"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
        py::arg("max_modules") = kMaxModules,
        "Derives the plant (steps: default the grammar's derivation length; seed: default the grammar's)");
    pyargs::defChecked(m, "instance_stats", &instanceStats, py::arg("grammar"), py::arg("steps") = py::none(),
                       py::arg("seed") = py::none(), py::arg("max_modules") = kMaxModules,
                       "The instance graph's statistics, as `lsys instance --json` prints them");
    pyargs::defChecked(
        m, "export", &exportPlant, py::arg("grammar"), py::arg("path"), py::arg("steps") = py::none(),
        py::arg("seed") = py::none(), py::arg("instanced").noconvert() = false, py::arg("sides") = 8,
        py::arg("skeleton").noconvert() = true, py::arg("max_modules") = kMaxModules, py::arg("geometry") = "drawn",
        "Writes the plant as .glb, .gltf or .obj, as `lsys export` does (geometry: 'drawn', the plant as "
        "plantfield draws it, or the turtle's 'frusta' or 'tubes'; flat and instanced)");
    pyargs::defChecked(m, "ramify", &ramify, py::arg("grammar"), py::arg("steps") = py::none(),
                       py::arg("seed") = py::none(), py::arg("max_modules") = kMaxModules,
                       "The plant's ramification matrix (Tankard 2001, section 2.2) as `lsys ramify --json` prints it: "
                       "{'orders': K, 'a': [a_1, ...], 'p': [[p_11], [p_21, p_22], ...]}");
    pyargs::defChecked(
        m, "ramified_tree", &ramifiedTree, py::arg("path"), py::arg("seed") = py::none(),
        py::arg("max_branches") = py::none(),
        "The tree a .ram.json file generates (seed, max_branches: default the file's), as a Grammar; raises "
        "LsystemError for a malformed file and RamificationBudgetError past the branch budget");

    bindRender(m);
}
