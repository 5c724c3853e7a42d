#include "lsystem/common/output_file.h"

#include "lsystem/common/file_reader.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lsys {
namespace fs = std::filesystem;

namespace {

std::string inQuotes(const fs::path& path) {
    std::string quoted = "'"; // appended, not a + b + c: GCC 12 warns falsely (-Wrestrict) on that
    quoted += path.string();
    quoted += '\'';
    return quoted;
}

// The file a write to `path` replaces: links followed, or `path` itself when
// nothing is there. Empty with `problem` set for a link that leads nowhere.
fs::path resolvedTarget(const fs::path& path, std::string& problem) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
    fs::path resolved = fs::canonical(path, ec);
    if (ec) problem = inQuotes(path) + " is a symbolic link to nothing";
    return resolved;
}

const char* kindOf(fs::file_type type) {
    switch (type) {
    case fs::file_type::directory: return "a folder";
    case fs::file_type::block:
    case fs::file_type::character: return "a device";
    case fs::file_type::fifo: return "a fifo";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
    }
}

// Same device and inode, links followed: a hard link, a symbolic link or a
// path spelt differently (../x, ./x) is the same file. A path that names
// nothing is no file's.
bool sameFile(const fs::path& a, const fs::path& b) {
    struct stat first {
    }, second{};
    return stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0 && first.st_dev == second.st_dev &&
           first.st_ino == second.st_ino;
}

std::string inputProblem(const fs::path& path, std::span<const fs::path> inputs) {
    std::vector<fs::path> all(inputs.begin(), inputs.end());
    const std::vector<fs::path> logged = loggedFileReads();
    all.insert(all.end(), logged.begin(), logged.end());
    for (const fs::path& input : all)
        if (sameFile(path, input))
            return inQuotes(path) + " is the input " + inQuotes(input) +
                   ": an output never replaces a file the run reads";
    return {};
}

} // namespace

std::string outputPathProblem(const fs::path& path, std::span<const fs::path> inputs) {
    if (path.empty()) return "the output path is empty";
    std::string problem;
    const fs::path target = resolvedTarget(path, problem);
    if (!problem.empty()) return problem;
    std::error_code ec;
    const fs::file_status status = fs::status(target, ec);
    if (fs::exists(status)) {
        if (status.type() != fs::file_type::regular)
            return inQuotes(path) + " is " + kindOf(status.type()) + ": only regular files are written";
        const fs::perms writable = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
        if ((status.permissions() & writable) == fs::perms::none) return inQuotes(path) + " is read-only";
        if (std::string clash = inputProblem(path, inputs); !clash.empty()) return clash;
    }
    const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec)) return "folder " + inQuotes(parent) + " does not exist";
    if (access(parent.c_str(), W_OK) != 0) return "folder " + inQuotes(parent) + " is not writable";
    return {};
}

OutputFile::OutputFile(const fs::path& target) : target_(target) {
    if (const std::string problem = outputPathProblem(target); !problem.empty())
        throw OutputRefusedError("cannot write " + inQuotes(target) + ": " + problem);
    std::string ignored;
    resolved_ = resolvedTarget(target, ignored);
    // mkstemp: a new file of our own, never an existing one of that name.
    std::string pattern = resolved_.string() + ".partial-XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("cannot create " + inQuotes(pattern) + ": " + std::strerror(errno));
    // mkstemp makes it 0600; give it the mode a new file gets, or the one it replaces.
    struct stat existing {};
    const mode_t umaskBits = umask(0);
    umask(umaskBits);
    const mode_t mode = stat(resolved_.c_str(), &existing) == 0 ? existing.st_mode & 07777 : (0666 & ~umaskBits);
    fchmod(fd, mode);
    close(fd);
    temporary_ = pattern;
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!out_) {
        std::error_code ec;
        fs::remove(temporary_, ec);
        throw std::runtime_error("cannot open " + inQuotes(temporary_) + ": " + std::strerror(errno));
    }
}

OutputFile::~OutputFile() {
    if (committed_) return;
    out_.close();
    std::error_code ignored;
    fs::remove(temporary_, ignored);
}

void OutputFile::commit() {
    out_.close();
    if (!out_) throw std::runtime_error("cannot write " + inQuotes(target_) + ": " + std::strerror(errno));
    std::error_code error;
    fs::rename(temporary_, resolved_, error);
    if (error) throw std::runtime_error("cannot write " + inQuotes(target_) + ": " + error.message());
    committed_ = true;
}

} // namespace lsys
