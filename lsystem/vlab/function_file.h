#pragma once
// vlab's function files (.func), which cpfg's func(id, x) reads: a curve y(x)
// over x in [0, 1] edited in vlab's funcedit, stored in one of two formats
// ("range: / points:" and "fver 1 1 / name: / samples: / flip: / points:"),
// and evaluated as cpfg evaluates it (cpfg's splinefun.cpp): a cubic
// B-spline over the control points, either sampled at `samples` evenly
// spaced x and interpolated linearly, or, without samples, searched by
// bisection for the point whose x is within 0.001 of the given x.
// Function sets (.fset, the view file's "function set:") hold several.

#include <filesystem>
#include <string>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/language/expression.h"

namespace lsys::vlab {

struct VlabFunction {
    std::string name; // the file's "name:", else its file name without .func
    // The control points, a point repeated as often as its multiplicity says.
    std::vector<double> xs;
    std::vector<double> ys;
    // y at x = i / (samples.size() - 1), as cpfg precomputes them; empty when
    // cpfg evaluates the curve itself on every call.
    std::vector<double> samples;
};

// y(x) as cpfg's func computes it; x is clamped to [0, 1].
double evaluateFunction(const VlabFunction& function, double x);

// The table func(id, x) reads (lsystem/language/expression.h): functions[i - 1]
// evaluated as evaluateFunction does for func(i, x).
FunctionTable functionTable(std::vector<VlabFunction> functions);

struct FunctionReadResult {
    VlabFunction function;
    std::vector<Diagnostic> diagnostics; // file:line:column of what is malformed
    bool ok() const { return diagnostics.empty(); }
};

// `samples` from the view file's "function: FILE SAMPLES" (-1: none given).
// As in cpfg, only the "range:" format uses it; an "fver" file's own
// "samples:" line decides for that format.
FunctionReadResult readFunctionFile(const std::filesystem::path& path, int samples = -1);
// The same, taking the samples it prepares from `samplesLeft`, which an
// object's function files and set share (see kMaxFunctionSamples).
FunctionReadResult readFunctionFile(const std::filesystem::path& path, int samples, int& samplesLeft);

struct FunctionSetReadResult {
    std::vector<VlabFunction> functions; // func(i, x) reads functions[i - 1]
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return diagnostics.empty(); }
};

// A function set ("funcgalleryver 1 1 / items: n" and n functions). cpfg
// names a set's functions for the L-system: it preprocesses the .l file with
// -DNAME=i for the i-th function's "name:", as written (generate.c,
// PreprocessLsystem), so that func(NAME, x) reads it. (The manual, §8.1.6,
// says this of every function file, in capitals; cpfg 6.6 does not.)
FunctionSetReadResult readFunctionSet(const std::filesystem::path& path);
FunctionSetReadResult readFunctionSet(const std::filesystem::path& path, int& samplesLeft);

// Most points a function may have (multiplicities included), and most
// samples one file, or all the functions of a set or of a vlab object
// together, may be prepared with: each sample is a bisection, so an object
// of hundreds of files of as many samples each would take minutes.
inline constexpr size_t kMaxFunctionPoints = 4096;
inline constexpr int kMaxFunctionSamples = 1 << 16;

} // namespace lsys::vlab
