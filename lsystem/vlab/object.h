#pragma once
// vlab objects: a folder holding a cpfg L-system (.l) and the files cpfg
// draws it with — a view file (.v), a colour map (.map) or material file
// (.mat), and the function (.func) and surface (.s) files the view file names
// (Měch 2005, "CPFG Version 4.0 User's Manual"; vlab's object browser runs
// the `cpfg` command line of the folder's `specifications`). Loading one gives
// a Grammar whose turtle draws as cpfg draws it: the view's angle, widths and
// their increments, colours and tropism in Grammar::style, the colours and
// surfaces in its PlantLook, the functions in func().

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lsystem/dialects/dialect.h"
#include "lsystem/language/parser.h"

namespace lsys::vlab {

struct ObjectFiles {
    std::filesystem::path lsystem;    // the .l
    std::filesystem::path view;       // empty: cpfg's defaults
    std::filesystem::path colorMap;   // cpfg -m
    std::filesystem::path materials;  // cpfg -M
    std::vector<std::string> ignored; // what the command line names that plantfield does not read, for a warning
};

// The files of the object at `path`: a folder, or a .l file in one. The
// first `cpfg` command line of the folder's `specifications` names them
// when it names this .l (or any, for a folder); otherwise the folder's only
// .l (or the one given) with the .v, .map or .mat of its stem, or the only
// one there is. nullopt with `problem` set when there is no .l or several.
std::optional<ObjectFiles> findObjectFiles(const std::filesystem::path& path, std::string& problem);

// Whether `path` names a vlab object rather than a bare plant file: a
// folder, or a .l with a view file or a specifications beside it.
bool isVlabObject(const std::filesystem::path& path);

// Every plant under `root`, sorted: plant files, and vlab objects (folders
// with a specifications file or a .l) as their folder, not their files.
std::vector<std::filesystem::path> findPlants(const std::filesystem::path& root);

// A plant file read for a tool or a scene.
struct PlantFile {
    ParseResult parsed; // the grammar with the object's style; every diagnostic and warning
    std::string file;   // the L-system's path, as diagnostics name it
    std::string source; // its text, which formatDiagnostics quotes
};

// A vlab object, with every diagnostic of every file it reads at its file,
// line and column (those of other files than the L-system carry their line).
PlantFile loadObject(const std::filesystem::path& path, ParseOptions options = {});

// Any plant path: a vlab object (isVlabObject), or a plant file in `dialect`
// (else the one its text or name says; lsystem/dialects/dialect.h).
PlantFile loadPlant(const std::filesystem::path& path, std::optional<Dialect> dialect = std::nullopt,
                    ParseOptions options = {});

} // namespace lsys::vlab
