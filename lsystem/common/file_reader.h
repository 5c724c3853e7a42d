#pragma once
// Reading a whole input file with a size limit, shared by the plant files
// (lsystem/language/parser.h), glTF surfaces (surfaces_gltf.cpp) and scene files
// (lsystem/common/json_reader.h); each names its own limit and words its own
// messages.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/common/error.h"

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

// The files a load tried to read, for reloading when one changes (plantfield
// --watch): while a ReadFileLog is alive, every path readFileUpTo (or a reader
// of its own calling noteFileRead) is asked for on the same thread is
// appended to it, found or not (a missing file that appears is a change too).
// Per thread, so that loads on other threads do not mix in; logs nest, each
// seeing the reads of its lifetime. Reading through these two functions is
// what lets the loaders report their files without each passing a list down.
class ReadFileLog {
public:
    ReadFileLog();
    ~ReadFileLog();
    ReadFileLog(const ReadFileLog&) = delete;
    ReadFileLog& operator=(const ReadFileLog&) = delete;

    // In the order first read, each once.
    const std::vector<std::filesystem::path>& paths() const { return paths_; }

private:
    friend void noteFileRead(const std::filesystem::path& path);
    friend std::vector<std::filesystem::path> loggedFileReads();
    std::vector<std::filesystem::path> paths_;
    ReadFileLog* outer_;
};

// Adds `path` to the thread's open ReadFileLogs (none: does nothing).
void noteFileRead(const std::filesystem::path& path);

// Every path the thread's open ReadFileLogs hold (the outermost sees every
// read of the inner ones): the files the run has read so far, which no output
// may replace (lsystem/common/output_file.h). Empty when no log is open.
std::vector<std::filesystem::path> loggedFileReads();

} // namespace lsys
