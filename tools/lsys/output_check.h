// The output rule (lsystem/common/output_file.h) as lsys's writing commands
// apply it: before loading, against the file named on the command line;
// after loading, against every file the load read as well (main keeps a
// lsys::ReadFileLog open for the whole run), so an export's .mtl landing on
// an include or a render onto a vlab object's view file is refused before the
// long work.
#pragma once

#include <filesystem>
#include <span>

namespace tools {

// Prints "lsys: error: ..." for the first of `outputs` that cannot be
// written or is a file the run reads (`input` or a logged read); true then.
bool outputRefused(std::span<const std::filesystem::path> outputs, const std::filesystem::path& input);

} // namespace tools
