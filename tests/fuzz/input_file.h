// The loaders fuzzed through a file (scenes, glTF) read a path: each input
// is written to a file in a folder of this process's own, overwritten by the
// next. The folder mirrors data/: its plants/, meshes/ and terrain/ link to
// the shipped ones, so a scene in scenes/ names L-systems as the shipped
// scenes do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace pf::fuzz {

// Writes the input to <temp>/plantfield-fuzz-<pid>/<relative> and returns the path.
std::filesystem::path writeInputFile(const uint8_t* data, size_t size, const std::string& relative);

} // namespace pf::fuzz
