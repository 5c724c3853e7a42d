// Output files written whole or not at all, and only where a file may be
// written: every tool's captures, exports, reports and plots go through here.
// The bytes go to a fresh temporary file beside the target, renamed onto it
// once complete, so a failure never leaves half a file and never clobbers an
// existing one. A target that exists must be a regular file with a write
// permission bit set (checked by mode, so even root does not replace a
// read-only file); a symbolic link is followed and stays a link. Devices,
// fifos, sockets and folders are refused: renaming over them would replace
// them (a capture to /dev/full would leave a PNG named /dev/full).
// An output is never one of the run's inputs: a target that is, links
// followed, the same file (device and inode) as a file the run reads is
// refused, so `--capture scene.json` or an .mtl landing on a plant file
// fails before any work instead of destroying what it was made from. The
// inputs are the paths a caller passes (those named on its command line,
// known before loading) and every file the thread's open ReadFileLogs
// recorded (lsystem/common/file_reader.h: the files its loads read, known
// only after loading), so a tool checks before loading, again after, and
// OutputFile once more when it opens the target.
#pragma once

#include <filesystem>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

namespace lsys {

// A target refused for where it points (outputPathProblem's reason): bad
// input, as a bad flag is, where a failed write is the machine's fault.
struct OutputRefusedError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Empty when `path` can be written as described above, otherwise the reason
// it cannot ("'x' is a folder", "folder 'y' does not exist", "'x' is the
// input 'y'", ...). Tools check it before any long work. `inputs` adds to the
// files the thread's ReadFileLogs recorded.
std::string outputPathProblem(const std::filesystem::path& path, std::span<const std::filesystem::path> inputs = {});

class OutputFile {
public:
    // Throws OutputRefusedError with outputPathProblem's reason (the inputs
    // being the thread's ReadFileLogs'), std::runtime_error when the
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
