#pragma once
// Reading a whole input file with a size limit, shared by the plant files
// (lsystem/parser.h), glTF surfaces (surfaces_gltf.cpp) and scene files
// (lsystem/json_reader.h); each names its own limit and words its own
// messages.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/error.h"

namespace lsys {

enum class FileProblem : unsigned char { None, Folder, CannotOpen, TooLarge, CannotRead };

struct FileBytes {
    std::string bytes; // empty unless problem is None
    FileProblem problem = FileProblem::None;
};

// The file's bytes, at most maxBytes: a regular file larger than that is
// refused from its size, anything else (a device, a fifo) is read in pieces
// and refused once it passes the limit, so /dev/zero stops there.
FileBytes readFileUpTo(const std::filesystem::path& path, size_t maxBytes);

// What is wrong with a file readFileUpTo(path, maxBytes) refused, to follow
// its name: "is a folder", "is missing or cannot be opened", "is larger than 4 MiB",
// "cannot be read"; empty for FileProblem::None.
std::string fileProblemText(FileProblem problem, size_t maxBytes);

// The text of a `kind` file ("surface", "function", "view"), or nullopt with
// a diagnostic in `diagnostics`: "the surface file 'PATH' is larger than 4 MiB".
std::optional<std::string> readTextFileOf(std::string_view kind, const std::filesystem::path& path, size_t maxBytes,
                                          std::vector<Diagnostic>& diagnostics);

} // namespace lsys
