#include "lsystem/vlab/function_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>

#include "lsystem/common/file_reader.h"
#include "lsystem/language/lexer.h"

namespace lsys::vlab {

namespace {

constexpr size_t kMaxFunctionFileBytes = size_t(4) << 20; // funcedit writes a few hundred bytes per function
constexpr int kMaxSetItems = 1024;
// cpfg's bisection stops once the curve's x is within this of the x asked
// for (splinefun.cpp, SplineFunction::_Value, MaxError).
constexpr double kBisectionTolerance = 0.001;
// cpfg halves without a bound and hangs on a curve whose x never comes that
// close. Here the search stops after this many halvings, the parameter then
// within 2^-50 of the curve's end, short of 1, where the curve drops to (0, 0).
constexpr int kMaxBisections = 50;
// The samples cpfg prepares a function in a set with (SplineFunction's
// constructor from an open file).
constexpr int kSetSamples = 100;

// The lines of a function file, taken one after the other; blank lines are
// skipped. Each comes as a Cursor so that diagnostics carry line and column.
class Lines : public ErrorReport {
public:
    Lines(std::string_view text, std::string file, std::vector<Diagnostic>& diagnostics)
        : ErrorReport{std::move(file), diagnostics}, lines_(splitLines(text)) {}

    std::optional<Cursor> next(const std::string& expected) {
        while (index_ < lines_.size()) {
            Cursor cursor{lines_[index_], 0, static_cast<int>(index_) + 1};
            ++index_;
            cursor.skipSpaces();
            if (!cursor.atEnd()) return cursor;
        }
        diagnostics.push_back({file, static_cast<int>(lines_.size()), 1, "the file ends too early", expected});
        return std::nullopt;
    }

private:
    std::vector<std::string_view> lines_;
    size_t index_ = 0;
};

// A number as cpfg's %f and std::stof read it (a float); none leaves the cursor.
std::optional<double> number(Cursor& cursor) {
    cursor.skipSpaces();
    const size_t begin = cursor.pos;
    while (!cursor.atEnd() && !std::isspace(static_cast<unsigned char>(cursor.peek()))) ++cursor.pos;
    const std::string token(cursor.text.substr(begin, cursor.pos - begin));
    char* end = nullptr;
    const float value = std::strtof(token.c_str(), &end);
    if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(value)) {
        cursor.pos = begin;
        return std::nullopt;
    }
    return value;
}

// A whole number in [least, most]; a diagnostic otherwise.
std::optional<int> count(Lines& lines, Cursor& cursor, const std::string& what, int least, int most) {
    cursor.skipSpaces();
    const Cursor at = cursor;
    const std::optional<double> value = number(cursor);
    if (!value || *value != std::floor(*value) || *value < least || *value > most) {
        lines.fail(at, "malformed " + what,
                   "a whole number from " + std::to_string(least) + " to " + std::to_string(most));
        return std::nullopt;
    }
    return static_cast<int>(*value);
}

bool lineEnd(Lines& lines, Cursor& cursor) {
    cursor.skipSpaces();
    return cursor.atEnd() || lines.fail(cursor, "unexpected text after the values", "end of line");
}

// The next line, which must begin with `label` ("points:").
std::optional<Cursor> labelled(Lines& lines, const std::string& label) {
    std::optional<Cursor> cursor = lines.next("'" + label + "'");
    if (cursor && !cursor->accept(label)) {
        lines.fail(*cursor, "expected '" + label + "'", "'" + label + "'");
        return std::nullopt;
    }
    return cursor;
}

// "label: n" on the next line.
std::optional<int> labelledCount(Lines& lines, const std::string& label, int least, int most) {
    std::optional<Cursor> cursor = labelled(lines, label);
    if (!cursor) return std::nullopt;
    std::optional<int> value = count(lines, *cursor, "'" + label + "' value", least, most);
    return value && lineEnd(lines, *cursor) ? value : std::nullopt;
}

// "x y" (and, with `multiplicity`, an optional third number: how many times
// the point counts, as funcedit writes repeated points).
bool point(Lines& lines, VlabFunction& function, bool multiplicity) {
    std::optional<Cursor> cursor = lines.next("a point 'x y'");
    if (!cursor) return false;
    const std::optional<double> x = number(*cursor);
    const std::optional<double> y = x ? number(*cursor) : std::nullopt;
    if (!y) return lines.fail(*cursor, "malformed point", "two numbers 'x y'");
    cursor->skipSpaces();
    const Cursor timesAt = *cursor;
    int times = 1;
    if (multiplicity && !cursor->atEnd()) {
        const std::optional<double> m = number(*cursor);
        if (!m || *m < 0) return lines.fail(timesAt, "malformed multiplicity", "a number of at least 0");
        times = static_cast<int>(std::min<double>(*m, kMaxFunctionPoints + 1.0)); // cpfg truncates it
    }
    if (!lineEnd(lines, *cursor)) return false;
    if (function.xs.size() + times > kMaxFunctionPoints)
        return lines.fail(timesAt, "too many points", "at most " + std::to_string(kMaxFunctionPoints));
    function.xs.insert(function.xs.end(), times, *x);
    function.ys.insert(function.ys.end(), times, *y);
    return true;
}

// "points: n" and the n points.
bool points(Lines& lines, VlabFunction& function, bool multiplicity) {
    std::optional<Cursor> at = labelled(lines, "points:");
    if (!at) return false;
    at->skipSpaces();
    const Cursor countAt = *at;
    const std::optional<int> n = count(lines, *at, "number of points", 4, kMaxFunctionPoints);
    if (!n || !lineEnd(lines, *at)) return false;
    for (int i = 0; i < *n; ++i)
        if (!point(lines, function, multiplicity)) return false;
    if (function.xs.size() < 4)
        return lines.fail(countAt, "fewer than 4 points once multiplicities count", "at least 4 points");
    return true;
}

// The span of cpfg's knot vector (splinefun.cpp, SplineFunction::Uk): a
// clamped uniform B-spline of order 4 over the n + 1 control points.
int knot(int j, int n) { return j < 4 ? 0 : j > n ? n - 2 : j - 3; }

// The Cox-de Boor basis N(k, order) at u, term by term as cpfg computes it.
double basis(int k, int order, double u, int n) {
    if (order == 1) return knot(k, n) <= u && u < knot(k + 1, n) ? 1.0 : 0.0;
    double sum = 0.0;
    if (const int span = knot(k + order - 1, n) - knot(k, n); span != 0)
        sum = (u - knot(k, n)) / span * basis(k, order - 1, u, n);
    if (const int span = knot(k + order, n) - knot(k + 1, n); span != 0)
        sum += (knot(k + order, n) - u) / span * basis(k + 1, order - 1, u, n);
    return sum;
}

struct CurvePoint {
    double x = 0.0, y = 0.0;
};

// The curve at parameter d in [0, 1] (cpfg's SplineFunction::P). Only the
// four basis functions around u are non-zero; the others add exact zeros.
// At d = 1 no knot interval holds u and the point is (0, 0), as in cpfg.
CurvePoint curve(const VlabFunction& function, double d) {
    const int n = static_cast<int>(function.xs.size()) - 1;
    const double u = d * (n - 2);
    const int last = std::min(static_cast<int>(std::floor(u)) + 3, n);
    CurvePoint sum;
    for (int k = std::max(last - 3, 0); k <= last; ++k) {
        const double weight = basis(k, 4, u, n);
        sum.x += function.xs[k] * weight;
        sum.y += function.ys[k] * weight;
    }
    return sum;
}

// y where the curve's x is within kBisectionTolerance of x, found by halving
// the parameter interval as cpfg does.
double bisect(const VlabFunction& function, double x) {
    double low = 0.0, high = 1.0;
    CurvePoint at;
    for (int i = 0; i < kMaxBisections; ++i) {
        const double check = (low + high) / 2.0;
        at = curve(function, check);
        (at.x > x ? high : low) = check;
        if (std::fabs(at.x - x) <= kBisectionTolerance) break;
    }
    return at.y;
}

// cpfg precomputes `samples` values when there are more than 2 and
// otherwise evaluates the curve on every call. Every sample is a bisection,
// so a file, or a set's or an object's functions together, may ask for
// kMaxFunctionSamples at most: `budget` is what is left of them (a set of a
// thousand functions of 65536 samples each would take many minutes).
bool prepare(Lines& lines, const Cursor& at, VlabFunction& function, int samples, int& budget) {
    if (samples <= 2) return true;
    if (samples > budget)
        return lines.fail(at, "the function asks for " + std::to_string(samples) + " samples, too many",
                          "at most " + std::to_string(kMaxFunctionSamples) +
                              " for a file, or a set's or an object's functions in all");
    budget -= samples;
    function.samples.resize(samples);
    for (int i = 0; i < samples; ++i) function.samples[i] = bisect(function, double(i) / double(samples - 1));
    return true;
}

// "range: a b" (already read; cpfg ignores the range), "points: n", n points.
std::optional<VlabFunction> rangeFormat(Lines& lines, const Cursor& first, int samples, int& budget) {
    VlabFunction function;
    if (!points(lines, function, false) || !prepare(lines, first, function, samples, budget)) return std::nullopt;
    return function;
}

// funcedit's optional "background:" and "backgroundXY:" lines, then its
// optional markers, then "flip:" (all ignored, as cpfg ignores them).
bool editorLines(Lines& lines) {
    std::optional<Cursor> cursor = lines.next("'flip:'");
    if (cursor && cursor->startsWith("background:")) {
        if (!labelled(lines, "backgroundXY:")) return false;
        cursor = lines.next("'flip:'");
    }
    if (cursor && cursor->accept("markers:")) {
        const std::optional<int> markers = count(lines, *cursor, "number of markers", 0, kMaxFunctionPoints);
        for (int i = 0; markers && i < *markers; ++i)
            if (!labelled(lines, "m")) return false;
        cursor = markers ? lines.next("'flip:'") : std::nullopt;
    }
    return cursor &&
           (cursor->startsWith("flip:") || lines.fail(*cursor, "expected 'flip:'", "'flip: on' or 'flip: off'"));
}

// "fver 1 1" (already read), "name: n", "samples: s", editor lines, points.
std::optional<VlabFunction> fverFormat(Lines& lines, int& budget) {
    VlabFunction function;
    std::optional<Cursor> name = labelled(lines, "name:");
    if (!name) return std::nullopt;
    name->skipSpaces();
    const size_t begin = name->pos;
    while (!name->atEnd() && !std::isspace(static_cast<unsigned char>(name->peek()))) ++name->pos;
    function.name = std::string(name->text.substr(begin, name->pos - begin)); // cpfg's "name: %s"
    if (function.name.empty()) return lines.failed(*name, "missing function name", "a name");
    std::optional<Cursor> samplesAt = labelled(lines, "samples:");
    if (!samplesAt) return std::nullopt;
    samplesAt->skipSpaces();
    Cursor value = *samplesAt;
    const std::optional<int> samples = count(lines, value, "'samples:' value", 0, kMaxFunctionSamples);
    if (!samples || !editorLines(lines) || !points(lines, function, true) ||
        !prepare(lines, *samplesAt, function, *samples, budget))
        return std::nullopt;
    return function;
}

// One function in either format, starting at the next line.
std::optional<VlabFunction> function(Lines& lines, int samples, int& budget) {
    std::optional<Cursor> first = lines.next("'range:' or 'fver 1 1'");
    if (!first) return std::nullopt;
    if (first->accept("range:")) {
        Cursor range = *first;
        if (!number(range) || !number(range)) return lines.failed(range, "malformed range", "two numbers");
        return rangeFormat(lines, *first, samples, budget);
    }
    if (!first->accept("fver")) return lines.failed(*first, "not a function file", "'range:' or 'fver 1 1'");
    Cursor version = *first;
    const std::optional<double> major = number(version);
    const std::optional<double> minor = major ? number(version) : std::nullopt;
    if (!minor || *major != 1 || *minor != 1)
        return lines.failed(*first, "unsupported function file version", "'fver 1 1'");
    return fverFormat(lines, budget);
}

} // namespace

double evaluateFunction(const VlabFunction& function, double x) {
    if (std::isnan(x)) return x;
    x = std::clamp(x, 0.0, 1.0);
    if (function.samples.empty()) return function.xs.size() < 4 ? 0.0 : bisect(function, x);
    // Linear interpolation between samples, weighted as cpfg weighs them (SplineFunction::_Value).
    const size_t last = function.samples.size() - 1;
    const double index = x * double(last);
    const size_t i = static_cast<size_t>(std::floor(index));
    if (i >= last) return function.samples[last];
    return (1.0 - index + double(i)) * function.samples[i] + (index - double(i)) * function.samples[i + 1];
}

FunctionTable functionTable(std::vector<VlabFunction> functions) {
    auto table = std::make_shared<std::vector<std::function<double(double)>>>();
    table->reserve(functions.size());
    for (VlabFunction& function : functions)
        table->push_back([function = std::move(function)](double x) { return evaluateFunction(function, x); });
    return table;
}

FunctionReadResult readFunctionFile(const std::filesystem::path& path, int samples) {
    int samplesLeft = kMaxFunctionSamples;
    return readFunctionFile(path, samples, samplesLeft);
}

FunctionReadResult readFunctionFile(const std::filesystem::path& path, int samples, int& samplesLeft) {
    FunctionReadResult result;
    std::optional<std::string> text = readTextFileOf("function", path, kMaxFunctionFileBytes, result.diagnostics);
    if (!text) return result;
    Lines lines(*text, path.string(), result.diagnostics);
    if (std::optional<VlabFunction> read = function(lines, samples, samplesLeft)) result.function = std::move(*read);
    if (result.function.name.empty()) result.function.name = path.stem().string();
    return result;
}

FunctionSetReadResult readFunctionSet(const std::filesystem::path& path) {
    int samplesLeft = kMaxFunctionSamples;
    return readFunctionSet(path, samplesLeft);
}

FunctionSetReadResult readFunctionSet(const std::filesystem::path& path, int& samplesLeft) {
    FunctionSetReadResult result;
    std::optional<std::string> text = readTextFileOf("function", path, kMaxFunctionFileBytes, result.diagnostics);
    if (!text) return result;
    Lines lines(*text, path.string(), result.diagnostics);
    std::optional<Cursor> header = lines.next("'funcgalleryver 1 1'");
    if (!header) return result;
    Cursor version = *header;
    if (!version.accept("funcgalleryver") || number(version) != 1.0 || number(version) != 1.0) {
        lines.fail(*header, "not a function set", "'funcgalleryver 1 1'");
        return result;
    }
    const std::optional<int> items = labelledCount(lines, "items:", 0, kMaxSetItems);
    for (int i = 0; items && i < *items; ++i) {
        std::optional<VlabFunction> read = function(lines, kSetSamples, samplesLeft);
        if (!read) return result;
        result.functions.push_back(std::move(*read));
    }
    return result;
}

} // namespace lsys::vlab
