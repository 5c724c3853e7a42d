// Output files written whole or not at all, and only where a file may be
// written: every tool's captures, exports, reports and plots go through here.
// The bytes go to a fresh temporary file beside the target, renamed onto it
// once complete, so a failure never leaves half a file and never clobbers an
// existing one. A target that exists must be a regular file with a write
// permission bit set (checked by mode, so even root does not replace a
// read-only file); a symbolic link is followed and stays a link. Devices,
// fifos, sockets and folders are refused: renaming over them would replace
// them (a capture to /dev/full would leave a PNG named /dev/full).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace lsys {

// Empty when `path` can be written as described above, otherwise the reason
// it cannot ("'x' is a folder", "folder 'y' does not exist", ...). Tools
// check it before any long work.
std::string outputPathProblem(const std::filesystem::path& path);

class OutputFile {
public:
    // Throws std::runtime_error with outputPathProblem's reason, or when the
    // temporary file cannot be created.
    explicit OutputFile(const std::filesystem::path& target);
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    // Removes the temporary file unless committed.
    ~OutputFile();

    std::ostream& stream() { return out_; }
    // Where the bytes are written before commit(), for writers that open the
    // file themselves (gnuplot): they replace its content.
    const std::filesystem::path& temporaryPath() const { return temporary_; }
    // Closes the stream and renames the temporary file onto the target;
    // throws naming the target when a write failed.
    void commit();

private:
    std::filesystem::path target_;   // as given, for messages
    std::filesystem::path resolved_; // the file replaced: symbolic links followed
    std::filesystem::path temporary_;
    std::ofstream out_;
    bool committed_ = false;
};

} // namespace lsys
