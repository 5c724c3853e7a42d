#pragma once
// Reading a whole input file with a size limit, shared by the plant files
// (lsystem/parser.h), glTF surfaces (surfaces_gltf.cpp) and scene files
// (engine/scene/json_reader.h); each names its own limit and words its own
// messages.

#include <cstddef>
#include <filesystem>
#include <string>

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

} // namespace lsys
