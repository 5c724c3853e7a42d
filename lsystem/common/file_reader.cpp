#include "lsystem/common/file_reader.h"

#include <algorithm>
#include <fstream>

namespace lsys {
namespace {

thread_local ReadFileLog* innermostReadLog = nullptr;

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
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return {{}, FileProblem::Folder};
    const bool regular = std::filesystem::is_regular_file(path, ec);
    const uintmax_t size = regular ? std::filesystem::file_size(path, ec) : 0;
    if (regular && !ec && size > maxBytes) return {{}, FileProblem::TooLarge};
    std::ifstream in(path, std::ios::binary);
    if (!in) return {{}, FileProblem::CannotOpen};
    FileBytes file;
    if (regular && !ec) file.bytes.reserve(static_cast<size_t>(size));
    char piece[1 << 16];
    while (in.read(piece, sizeof piece) || in.gcount() > 0) {
        file.bytes.append(piece, static_cast<size_t>(in.gcount()));
        if (file.bytes.size() > maxBytes) return {{}, FileProblem::TooLarge}; // grew while read, or no end
    }
    if (in.bad()) return {{}, FileProblem::CannotRead};
    return file;
}

std::string fileProblemText(FileProblem problem, size_t maxBytes) {
    switch (problem) {
    case FileProblem::None: return {};
    case FileProblem::Folder: return "is a folder";
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
