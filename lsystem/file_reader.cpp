#include "lsystem/file_reader.h"

#include <fstream>

namespace lsys {

FileBytes readFileUpTo(const std::filesystem::path& path, size_t maxBytes) {
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

} // namespace lsys
