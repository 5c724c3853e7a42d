#include "lsystem/common/file_reader.h"

#include <algorithm>
#include <cerrno>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lsys {
namespace {

thread_local ReadFileLog* innermostReadLog = nullptr;

// Closes the descriptor on every way out of readFileUpTo.
struct OpenFile {
    int descriptor = -1;
    ~OpenFile() {
        if (descriptor >= 0) ::close(descriptor);
    }
};

} // namespace

ReadFileLog::ReadFileLog() : outer_(innermostReadLog) { innermostReadLog = this; }

ReadFileLog::~ReadFileLog() { innermostReadLog = outer_; }

void noteFileRead(const std::filesystem::path& path) {
    const std::filesystem::path normal = path.lexically_normal();
    for (ReadFileLog* log = innermostReadLog; log; log = log->outer_)
        if (std::find(log->paths_.begin(), log->paths_.end(), normal) == log->paths_.end())
            log->paths_.push_back(normal);
}

std::vector<std::filesystem::path> loggedFileReads() {
    const ReadFileLog* outermost = innermostReadLog;
    while (outermost && outermost->outer_) outermost = outermost->outer_;
    return outermost ? outermost->paths_ : std::vector<std::filesystem::path>{};
}

FileBytes readFileUpTo(const std::filesystem::path& path, size_t maxBytes) {
    noteFileRead(path);
    // O_NONBLOCK: opening a fifo without a writer returns at once instead of
    // waiting for one; the file's type is then read from the descriptor.
    const OpenFile file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    struct stat status {};
    if (file.descriptor < 0) {
        // A socket cannot be opened at all: name it from its path.
        const bool exists = ::stat(path.c_str(), &status) == 0;
        if (exists && S_ISDIR(status.st_mode)) return {{}, FileProblem::Folder};
        return {{}, exists && !S_ISREG(status.st_mode) ? FileProblem::NotRegular : FileProblem::CannotOpen};
    }
    if (::fstat(file.descriptor, &status) != 0) return {{}, FileProblem::CannotRead};
    if (S_ISDIR(status.st_mode)) return {{}, FileProblem::Folder};
    if (!S_ISREG(status.st_mode)) return {{}, FileProblem::NotRegular};
    if (uintmax_t(status.st_size) > maxBytes) return {{}, FileProblem::TooLarge};
    FileBytes read;
    read.bytes.reserve(size_t(status.st_size));
    char piece[1 << 16];
    for (;;) {
        const ssize_t got = ::read(file.descriptor, piece, sizeof piece);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return {{}, FileProblem::CannotRead};
        if (got == 0) return read;
        read.bytes.append(piece, size_t(got));
        if (read.bytes.size() > maxBytes) return {{}, FileProblem::TooLarge}; // grew while read
    }
}

std::string fileProblemText(FileProblem problem, size_t maxBytes) {
    switch (problem) {
    case FileProblem::None: return {};
    case FileProblem::Folder: return "is a folder";
    case FileProblem::NotRegular: return "is not a regular file (a fifo, a device or a socket)";
    case FileProblem::CannotOpen: return "is missing or cannot be opened";
    case FileProblem::TooLarge: return "is larger than " + std::to_string(maxBytes >> 20) + " MiB";
    case FileProblem::CannotRead: return "cannot be read";
    }
    return {};
}

std::optional<std::string> readTextFileOf(std::string_view kind, const std::filesystem::path& path, size_t maxBytes,
                                          std::vector<Diagnostic>& diagnostics) {
    FileBytes read = readFileUpTo(path, maxBytes);
    if (read.problem == FileProblem::None) return std::move(read.bytes);
    diagnostics.push_back(
        {path.string(), 0, 0,
         "the " + std::string(kind) + " file '" + path.string() + "' " + fileProblemText(read.problem, maxBytes)});
    return std::nullopt;
}

} // namespace lsys
