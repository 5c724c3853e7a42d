// Progress on stderr: a bar redrawn in place on a terminal, otherwise one
// line per finished count (logs stay short).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pf {

struct CountResult;

struct SweepProgress {
    bool terminal = false;
    size_t countTotal = 0; // counts in the sweep
    size_t countIndex = 0; // the count being measured
    uint64_t plants = 0;
};

SweepProgress startProgress(size_t countTotal);
// Terminal only: redraws the bar with what is happening ("naive frame 3/12").
// `fraction` is how far the current count is, 0 to 1.
void showProgress(const SweepProgress& progress, double fraction, const std::string& what);
// Clears the bar and prints the count's one-line result.
void finishCount(const SweepProgress& progress, const CountResult& result);

} // namespace pf
