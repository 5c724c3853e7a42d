#include "progress.h"

#include "sweep.h"

#include <cstdio>

#include <unistd.h>

namespace pf {

SweepProgress startProgress(size_t countTotal) {
    SweepProgress p;
    p.terminal = isatty(fileno(stderr));
    p.countTotal = countTotal;
    return p;
}

void showProgress(const SweepProgress& p, double fraction, const std::string& what) {
    if (!p.terminal) return;
    constexpr int kWidth = 30;
    const double whole = (double(p.countIndex) + fraction) / double(p.countTotal);
    const int filled = int(whole * kWidth + 0.5);
    std::fprintf(stderr, "\rplantbench [%.*s%.*s] %3.0f%%  count %zu/%zu, %llu plants: %s\x1b[K", filled,
                 "##############################", kWidth - filled, "..............................", whole * 100.0,
                 p.countIndex + 1, p.countTotal, static_cast<unsigned long long>(p.plants), what.c_str());
}

void finishCount(const SweepProgress& p, const CountResult& r) {
    if (p.terminal) std::fprintf(stderr, "\r\x1b[K");
    std::fprintf(stderr, "plantbench: %zu/%zu: %llu plants (built in %.1f s): frame %.2f ms median", p.countIndex + 1,
                 p.countTotal, static_cast<unsigned long long>(r.count), r.buildSeconds, r.driven.frameMs.median);
    if (!r.alongPath.empty())
        std::fprintf(stderr, " (the worst of %zu camera times, at t = %.1f s)", r.alongPath.size(), r.time);
    if (r.naive)
        std::fprintf(stderr, ", naive %.2f ms (%.1fx)", r.naive->frameMs.median,
                     r.naive->frameMs.median / r.driven.frameMs.median);
    if (!r.note.empty()) std::fprintf(stderr, "; %s", r.note.c_str());
    std::fprintf(stderr, "\n");
}

} // namespace pf
