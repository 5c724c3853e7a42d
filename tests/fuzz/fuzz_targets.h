// One fuzz input: parse it as a .lsys file and, when it parses, derive a few
// steps under a small module budget, then run the turtle. Shared by the
// libFuzzer binary and the corpus-replay test so both exercise the same path.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pf::fuzz {

void runLsysInput(const uint8_t* data, size_t size);

} // namespace pf::fuzz
