#include "lsystem/vlab/object.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "lsystem/common/file_reader.h"
#include "lsystem/vlab/color_files.h"
#include "lsystem/vlab/function_file.h"
#include "lsystem/vlab/surface_file.h"
#include "lsystem/vlab/view_file.h"

namespace lsys::vlab {

namespace fs = std::filesystem;

namespace {

// vlab's object specifications are a page of menu items; a megabyte is far past any.
constexpr size_t kMaxSpecificationsBytes = size_t(1) << 20;

// cpfg's options that take arguments (control.c, the usage it prints), and
// how many; the files among them are read by ObjectFiles.
size_t argumentCount(const std::string& option) {
    if (option == "-w" || option == "-wp") return 2;
    if (option == "-m" || option == "-m1" || option == "-m2" || option == "-M" || option == "-M1" || option == "-M2" ||
        option == "-e" || option == "-wt" || option == "-c" || option == "-homo" || option == "-str" ||
        option == "-rgb" || option == "-tga" || option == "-ray" || option == "-pov")
        return 1;
    return 0;
}

// Reads one cpfg command line's words into files of `folder`; false when it names no .l.
bool readCommandLine(const std::vector<std::string>& words, const fs::path& folder, ObjectFiles& files) {
    for (size_t i = 1; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (word.starts_with("-")) {
            const size_t count = argumentCount(word);
            if (i + count >= words.size()) break; // an option without its arguments ends the line
            const std::string argument = count > 0 ? words[i + 1] : std::string();
            if (word == "-m" || word == "-m1")
                files.colorMap = folder / argument;
            else if (word == "-M" || word == "-M1")
                files.materials = folder / argument;
            else if (word == "-e" || word == "-m2" || word == "-M2")
                files.ignored.push_back(word + " " + argument);
            i += count;
            continue;
        }
        const std::string extension = fs::path(word).extension().string();
        if (extension == ".l")
            files.lsystem = folder / word;
        else if (extension == ".v")
            files.view = folder / word;
        else if (extension == ".a" || extension == ".e")
            files.ignored.push_back(word);
    }
    return !files.lsystem.empty();
}

// The first cpfg command line of the folder's specifications that names
// `wanted` (any .l when empty).
std::optional<ObjectFiles> fromSpecifications(const fs::path& folder, const fs::path& wanted) {
    const FileBytes specifications = readFileUpTo(folder / "specifications", kMaxSpecificationsBytes);
    if (specifications.problem != FileProblem::None) return std::nullopt;
    std::istringstream lines(specifications.bytes);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream wordStream(line);
        std::vector<std::string> words;
        for (std::string word; wordStream >> word;) words.push_back(word);
        if (words.empty() || words[0] != "cpfg") continue;
        ObjectFiles files;
        if (readCommandLine(words, folder, files) && (wanted.empty() || fs::equivalent(files.lsystem, wanted)))
            return files;
    }
    return std::nullopt;
}

// The folder's files with this extension, sorted (directory order is not stable).
std::vector<fs::path> filesWithExtension(const fs::path& folder, const std::string& extension) {
    std::vector<fs::path> found;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
        if (entry.is_regular_file(error) && entry.path().extension() == extension) found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    return found;
}

// The file of the L-system's stem with this extension, else the only one there is.
fs::path companion(const fs::path& lsystem, const std::string& extension) {
    fs::path same = lsystem;
    same.replace_extension(extension);
    if (fs::is_regular_file(same)) return same;
    const std::vector<fs::path> all = filesWithExtension(lsystem.parent_path(), extension);
    return all.size() == 1 ? all.front() : fs::path();
}

std::string listed(const std::vector<fs::path>& paths) {
    std::string text;
    for (const fs::path& path : paths) text += (text.empty() ? "" : ", ") + path.filename().string();
    return text;
}

Material colorMaterial(const ColorEntry& entry, size_t index) {
    Material material;
    material.name = "colour " + std::to_string(index);
    material.albedo = entry.diffuse; // an index a material file leaves out has cpfg's default, white
    return material;
}

std::shared_ptr<const std::vector<Material>> paletteOf(const ColorTable& colors) {
    auto palette = std::make_shared<std::vector<Material>>();
    for (size_t i = 0; i < colors.size(); ++i) palette->push_back(colorMaterial(colors[i], i));
    return palette;
}

// cpfg's view file drives the turtle (interpret.c, InitializeTurtle and the
// ! # ; , cases): widths step by the increment, not by ABOP's factor.
void applyView(const ViewFile& view, Grammar& grammar) {
    grammar.angle = view.angleIncrement;
    grammar.width = view.initialLineWidth;
    TurtleStyle& style = grammar.style;
    style.widthFactor = 1.0;
    style.widthIncrement = view.lineWidthIncrement;
    style.colorIncrement = view.colorIncrement;
    style.material = static_cast<uint32_t>(((view.initialColor % 256) + 256) % 256);
    style.tropism = view.tropismDirection;
    style.elasticity = view.initialElasticity;
    style.movements = view.movements;
    style.pixelLines = view.lineStyle == LineStyle::Pixel;
}

void append(std::vector<Diagnostic>& to, std::vector<Diagnostic> from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// Diagnostics of the object's other files carry their own line, since
// formatDiagnostics quotes the L-system's.
void quoteOtherFiles(std::vector<Diagnostic>& diagnostics, const std::string& lsystemFile) {
    for (Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.file == lsystemFile || !diagnostic.sourceLine.empty() || diagnostic.line <= 0) continue;
        const FileBytes text = readFileUpTo(diagnostic.file, kMaxSourceBytes);
        std::istringstream lines(text.bytes);
        std::string line;
        for (int i = 0; i < diagnostic.line && std::getline(lines, line); ++i) {}
        diagnostic.sourceLine = line;
    }
}

// The object's own files, read into what the parser and the turtle take.
struct ObjectLook {
    ViewFile view;
    PlantLook look;
    FunctionTable functions;
    std::map<std::string, int> functionNames; // the set's names and their ids, for the preprocessor
};

// A warning at `line` of the view file.
void warnInView(PlantFile& plant, const ObjectFiles& files, int line, std::string message) {
    plant.parsed.warnings.push_back({files.view.string(), line, 1, std::move(message), {}, {}, Severity::Warning});
}

// Whether a file the view file names at `line` is missing, which a warning
// then says. cpfg reads on without it: it skips a surface file that is not
// there (interpret.c, "surface:", access(F_OK)), makes a function file it
// cannot open a curve of 0 (splinefun.cpp, SplineFunction::_Default) and a
// function set it cannot open no functions (splinearr.cpp, ReadGallery).
bool missing(const std::string& named, const ObjectFiles& files, int line, const std::string& what,
             const std::string& instead, PlantFile& plant) {
    std::error_code error;
    if (fs::exists(files.lsystem.parent_path() / named, error)) return false;
    warnInView(plant, files, line, "the " + what + " file '" + named + "' does not exist: " + instead + ", as in cpfg");
    return true;
}

bool isIdentifier(const std::string& name) {
    auto identifierChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    return !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
           std::all_of(name.begin(), name.end(), identifierChar);
}

// The set's functions, named for the L-system as cpfg names them: it
// preprocesses the .l with -DNAME=i for the i-th function (generate.c,
// PreprocessLsystem). cpfg's preprocessor rejects a -D whose name is no C
// identifier, which then names nothing.
void readSet(const ViewFunctionSet& set, const ObjectFiles& files, ObjectLook& object,
             std::vector<VlabFunction>& functions, int& samplesLeft, PlantFile& plant) {
    if (missing(set.file, files, set.line, "function set", "it adds no functions", plant)) return;
    FunctionSetReadResult read = readFunctionSet(files.lsystem.parent_path() / set.file, samplesLeft);
    append(plant.parsed.diagnostics, std::move(read.diagnostics));
    for (VlabFunction& function : read.functions) {
        functions.push_back(std::move(function));
        const std::string& name = functions.back().name;
        const int id = static_cast<int>(functions.size());
        if (!set.names || name.empty()) continue;
        if (isIdentifier(name))
            object.functionNames[name] = id; // a name given twice: the later -D wins, as in cpp
        else
            warnInView(plant, files, set.line,
                       "the function set's function '" + name + "' (func(" + std::to_string(id) +
                           ", x)) has a name that is no C identifier: cpfg's preprocessor rejects it, so it names "
                           "nothing");
    }
}

ObjectLook readObjectLook(const ObjectFiles& files, PlantFile& plant) {
    ObjectLook object;
    std::vector<Diagnostic>& errors = plant.parsed.diagnostics;
    if (!files.view.empty()) {
        ViewReadResult view = readViewFile(files.view);
        append(errors, std::move(view.diagnostics));
        append(plant.parsed.warnings, std::move(view.warnings));
        object.view = std::move(view.view);
    }
    const fs::path folder = files.lsystem.parent_path();
    std::vector<VlabFunction> functions;
    int samplesLeft = kMaxFunctionSamples; // shared by all the object's functions
    if (object.view.functionSet) readSet(*object.view.functionSet, files, object, functions, samplesLeft, plant);
    for (const ViewFunction& function : object.view.functions) {
        const fs::path path = folder / function.file;
        if (missing(function.file, files, function.line, "function", "its function is 0 everywhere", plant)) {
            functions.push_back(VlabFunction{.name = path.stem().string()});
            continue;
        }
        FunctionReadResult read = readFunctionFile(path, function.samples, samplesLeft);
        append(errors, std::move(read.diagnostics));
        functions.push_back(std::move(read.function));
    }
    object.functions = functionTable(std::move(functions));
    auto surfaces = std::make_shared<std::vector<SurfaceMesh>>();
    for (const ViewSurface& surface : object.view.surfaces) {
        const fs::path path = folder / surface.file;
        if (missing(surface.file, files, surface.line, "surface", "~" + surface.id + " draws nothing", plant)) {
            surfaces->push_back(SurfaceMesh{.name = surface.id}); // found before the library's, and empty
            continue;
        }
        SurfaceReadResult read =
            readSurfaceFile(path, surface.id, surface.scale, surface.sPrecision, surface.tPrecision);
        append(errors, std::move(read.diagnostics));
        read.mesh.endPoint = read.endPoint;
        surfaces->push_back(std::move(read.mesh));
    }
    object.look.surfaces = std::move(surfaces);
    if (!files.colorMap.empty() || !files.materials.empty()) {
        ColorReadResult colors =
            files.colorMap.empty() ? readMaterialFile(files.materials) : readColorMap(files.colorMap);
        if (colors.error) errors.push_back(*colors.error);
        object.look.palette = paletteOf(colors.colors);
    }
    for (const std::string& ignored : files.ignored)
        plant.parsed.warnings.push_back({files.lsystem.string(),
                                         0,
                                         0,
                                         "the object's cpfg command line names '" + ignored +
                                             "', which plantfield does not read (animation, environment or a "
                                             "second colour map)",
                                         {},
                                         {},
                                         Severity::Warning});
    return object;
}

} // namespace

std::optional<ObjectFiles> findObjectFiles(const fs::path& path, std::string& problem) {
    const bool folder = fs::is_directory(path);
    const fs::path directory = folder ? path : path.parent_path();
    const fs::path wanted = folder ? fs::path() : path;
    if (std::optional<ObjectFiles> named = fromSpecifications(directory, wanted)) return named;
    ObjectFiles files;
    files.lsystem = wanted;
    if (folder) {
        const std::vector<fs::path> lsystems = filesWithExtension(directory, ".l");
        if (lsystems.size() != 1) {
            problem = lsystems.empty() ? "holds no cpfg L-system (.l file)"
                                       : "holds several L-systems (" + listed(lsystems) +
                                             ") and no specifications naming one on its cpfg line: name the .l";
            return std::nullopt;
        }
        files.lsystem = lsystems.front();
    }
    files.view = companion(files.lsystem, ".v");
    files.colorMap = companion(files.lsystem, ".map");
    if (files.colorMap.empty()) files.materials = companion(files.lsystem, ".mat");
    return files;
}

bool isVlabObject(const fs::path& path) {
    std::error_code error;
    if (fs::is_directory(path, error)) return true;
    if (path.extension() != ".l") return false;
    fs::path view = path;
    view.replace_extension(".v");
    return fs::is_regular_file(view, error) || fs::is_regular_file(path.parent_path() / "specifications", error);
}

std::vector<fs::path> findPlants(const fs::path& root) {
    std::vector<fs::path> plants;
    std::error_code error;
    for (fs::recursive_directory_iterator it(root, error), end; !error && it != end; it.increment(error)) {
        if (it->is_directory(error) &&
            (fs::exists(it->path() / "specifications", error) || !filesWithExtension(it->path(), ".l").empty())) {
            plants.push_back(it->path());
            it.disable_recursion_pending();
        } else if (it->is_regular_file(error)) {
            plants.push_back(it->path());
        }
    }
    std::sort(plants.begin(), plants.end());
    return plants;
}

namespace {

// Reads plant.file and parses it in `dialect` (else the one its text or name
// says), keeping what is already in plant.parsed (the object's other files'
// diagnostics) after the file's own.
void readAndParse(PlantFile& plant, std::optional<Dialect> dialect, const ParseOptions& options) {
    std::string problem;
    plant.source = readTextFile(plant.file, problem);
    ParseResult parsed;
    if (!problem.empty())
        parsed.diagnostics.push_back({plant.file, 0, 0, "cannot read file: it " + problem});
    else
        parsed = parseDialect(dialectOfFile(dialect, plant.source, plant.file), plant.source, options);
    append(parsed.diagnostics, std::move(plant.parsed.diagnostics));
    append(parsed.warnings, std::move(plant.parsed.warnings));
    plant.parsed = std::move(parsed);
}

} // namespace

PlantFile loadObject(const fs::path& path, ParseOptions options) {
    PlantFile plant;
    plant.file = path.string();
    std::string problem;
    const std::optional<ObjectFiles> files = findObjectFiles(path, problem);
    if (!files) {
        plant.parsed.diagnostics.push_back({plant.file, 0, 0, "the vlab object " + problem});
        return plant;
    }
    plant.file = files->lsystem.string();
    const ObjectLook object = readObjectLook(*files, plant);
    options.file = plant.file;
    options.functions = object.functions;
    // The tool's own -D (the user's) wins over a function's name.
    for (const auto& [name, id] : object.functionNames) options.defines.try_emplace(name, id);
    readAndParse(plant, std::nullopt, options);
    applyView(object.view, plant.parsed.grammar);
    plant.parsed.grammar.style.look = object.look;
    quoteOtherFiles(plant.parsed.diagnostics, plant.file);
    quoteOtherFiles(plant.parsed.warnings, plant.file);
    return plant;
}

PlantFile loadPlant(const fs::path& path, std::optional<Dialect> dialect, ParseOptions options) {
    if (isVlabObject(path)) return loadObject(path, std::move(options));
    PlantFile plant;
    plant.file = path.string();
    if (options.file == "<input>") options.file = plant.file;
    readAndParse(plant, dialect, options);
    return plant;
}

} // namespace lsys::vlab
