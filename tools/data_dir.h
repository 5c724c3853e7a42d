#pragma once
// Where the tools find the data folder (plants, meshes, scenes): docs/INSTALL.md.

#include <filesystem>
#include <optional>
#include <string>

namespace pf {

// The data folder, in this order:
//   1. the environment variable PLANTFIELD_DATA_DIR, when set and not empty;
//   2. <directory of the running binary>/<installDataRelative>, when that
//      folder exists: an installed binary (bin/plantfield) reads
//      share/plantfield/data of its own prefix, wherever the tree was
//      installed or moved to;
//   3. `compiledIn`, the source tree's data/ (what a binary in the build tree
//      uses).
// The result is lexically normal ("bin/../share" becomes "share").
std::string dataDirectory();

// The same rules with every input given: what dataDirectory() runs with the
// environment, /proc/self/exe and the paths compiled in. `environment` is
// nullptr when the variable is unset; `executable` empty when unknown.
std::string dataDirectoryFrom(const char* environment, const std::filesystem::path& executable,
                              const std::filesystem::path& installDataRelative, const std::string& compiledIn);

} // namespace pf
