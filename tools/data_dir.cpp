#include "tools/data_dir.h"

#include <cstdlib>
#include <system_error>

// Compiled in by the target that builds this file (tools/plantfield/CMakeLists.txt).
#ifndef PLANTFIELD_DATA_DIR
#error "PLANTFIELD_DATA_DIR (the source tree's data folder) must be defined"
#endif
#ifndef PLANTFIELD_INSTALL_DATA_RELATIVE
#define PLANTFIELD_INSTALL_DATA_RELATIVE "../share/plantfield/data"
#endif

namespace pf {

std::string dataDirectoryFrom(const char* environment, const std::filesystem::path& executable,
                              const std::filesystem::path& installDataRelative, const std::string& compiledIn) {
    if (environment && *environment) return environment;
    if (!executable.empty()) {
        const std::filesystem::path installed = (executable.parent_path() / installDataRelative).lexically_normal();
        std::error_code error;
        if (std::filesystem::is_directory(installed, error)) {
            std::string text = installed.string();
            if (text.size() > 1 && text.back() == '/') text.pop_back();
            return text;
        }
    }
    return compiledIn;
}

std::string dataDirectory() {
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    return dataDirectoryFrom(std::getenv("PLANTFIELD_DATA_DIR"), error ? std::filesystem::path() : executable,
                             PLANTFIELD_INSTALL_DATA_RELATIVE, PLANTFIELD_DATA_DIR);
}

} // namespace pf
