#include "lsystem/vlab/view_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <tuple>
#include <type_traits>

#include <glm/geometric.hpp>

#include "lsystem/common/file_reader.h"
#include "lsystem/dialects/c_preprocessor.h"

namespace lsys::vlab {

namespace {

constexpr size_t kMaxViewFileBytes = size_t(1) << 20;
// Diagnostics kept per list: binary garbage would make one for every line.
constexpr size_t kMaxListed = 1000;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The text with its /* */ and // comments made spaces (newlines kept, so
// lines and columns stay): the preprocessor removes them before cpfg reads a
// view file, and cpfg's own NextLabel skips /* */ (cpfg's interpret.c).
std::string withoutComments(std::string_view text) {
    std::string out(text);
    bool quoted = false; // "winfont:" names its font in quotes
    for (size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '\n' || out[i] == '"') quoted = out[i] == '"' && !quoted;
        if (quoted || out[i] != '/' || (out[i + 1] != '/' && out[i + 1] != '*')) continue;
        const size_t close = out[i + 1] == '/' ? out.find('\n', i) : out.find("*/", i + 2);
        const size_t end = close == std::string::npos ? out.size() : close + (out[i + 1] == '*' ? 2 : 0);
        for (size_t j = i; j < end; ++j)
            if (out[j] != '\n') out[j] = ' ';
        i = end - 1;
    }
    return out;
}

// A label or value as a message shows it: quoted, short, control bytes and binary as '?'.
std::string shown(std::string_view text) {
    std::string out = std::string("'").append(text.substr(0, 60));
    for (char& c : out) c = c >= 0x20 && c < 0x7f ? c : '?';
    return out + (text.size() > 60 ? "...'" : "'");
}

// How many characters of `s` scanf's %f (or %d, without `fraction`) reads.
size_t numberLength(std::string_view s, bool fraction) {
    size_t i = s.starts_with('+') || s.starts_with('-') ? 1 : 0, mantissa = 0;
    auto digits = [&] {
        for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) ++mantissa;
    };
    digits();
    if (fraction && i < s.size() && s[i] == '.') ++i, digits();
    if (mantissa == 0) return 0;
    const size_t mark = i, before = mantissa;
    if (fraction && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        i += i + 1 < s.size() && (s[i + 1] == '+' || s[i + 1] == '-') ? 2 : 1;
        digits();
    }
    return mantissa > before ? i : mark;
}

// A value a format read: a number (%f, %d) or text (%s, %c), and where.
struct Value {
    double number = 0.0;
    std::string_view text;
    size_t at = 0;
};
using Values = std::vector<Value>;

// cpfg's way of reading a view file (interpret.c, NextLabel and ReadViewData):
// a label runs from the first non-space to ':' (or is "#"), is matched
// exactly, and its values are scanned with cpfg's own fscanf format; what is
// left on the line after them is read as the next label. Values must be on
// the label's line (fscanf would go on to the next line and swallow it).
class Reader {
public:
    Reader(std::string_view text, std::string file) : text_(text), markerFile_(std::move(file)) {
        for (size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') lineStarts_.push_back(i + 1);
    }

    ViewReadResult result;
    std::string_view label, example; // the label being read, and an example of its values
    ViewFile& view() { return result.view; }

    void run();
    void skipLine() { pos_ = std::min(text_.find('\n', pos_), text_.size()); }
    // The rest of the line, as cpfg's fgets reads it, and where it starts; the line is then read.
    std::pair<std::string_view, size_t> restOfLine() {
        const size_t from = pos_;
        skipLine();
        return {text_.substr(from, pos_ - from), from};
    }
    bool accept(std::string_view s) { return text_.substr(pos_).starts_with(s) && (pos_ += s.size(), true); }
    // `format` as fscanf reads it (' ', %f, %d, %s, %c, other characters
    // literally), within the line; after '|' what is missing is no error.
    bool scan(std::string_view format, Values& values);

    // An error at `at`; the rest of the line is skipped, as CheckInputError skips it.
    void fail(std::string_view expected, size_t at, std::string message = {}) {
        if (message.empty()) message = "bad value for " + shown(label);
        add(result.diagnostics, at, message,
            std::string(expected) + ", as in " + shown(std::string(label) + " " + std::string(example)));
        skipLine();
    }
    void warn(std::string message, size_t at = std::string_view::npos) {
        add(result.warnings, at == std::string_view::npos ? labelStart_ : at, std::move(message), {});
    }
    int labelLine() const { return locate(labelStart_).first; }
    // "# 12 "file"" (cpp's line marker): the next line is line 12 of file.
    void setMarker(int fileLine, std::string_view name) {
        if (!name.empty()) markerFile_ = std::string(name);
        markerTextLine_ = textLine(labelStart_), markerFileLine_ = fileLine;
    }

private:
    size_t skipBlanks() {
        return pos_ = size_t(std::find_if_not(text_.begin() + pos_, text_.end(), isBlank) - text_.begin());
    }
    bool atBlank() const { return pos_ == text_.size() || text_[pos_] == '\n' || isBlank(text_[pos_]); }
    bool convert(char kind, Values& values);
    template <typename T>
    bool number(Values& values);
    int textLine(size_t at) const {
        return int(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), at) - lineStarts_.begin());
    }
    // The line (after line markers) and column of `at`.
    std::pair<int, int> locate(size_t at) const {
        const int line = textLine(at), column = int(at - lineStarts_[size_t(line) - 1]) + 1;
        return {markerTextLine_ > 0 ? markerFileLine_ + line - markerTextLine_ - 1 : line, column};
    }
    void add(std::vector<Diagnostic>& list, size_t at, std::string message, std::string expected) {
        if (list.size() > kMaxListed) return;
        if (list.size() == kMaxListed) message = "more problems follow, not listed", expected.clear();
        const auto [line, column] = locate(at);
        const Severity severity = &list == &result.warnings ? Severity::Warning : Severity::Error;
        list.push_back({markerFile_, line, column, std::move(message), std::move(expected), {}, severity});
    }

    std::string_view text_;
    std::string markerFile_; // the file named by the last line marker, or the file read
    std::vector<size_t> lineStarts_{0};
    size_t pos_ = 0, labelStart_ = 0;
    int markerTextLine_ = 0, markerFileLine_ = 0; // the last line marker's line, and the line it names; 0: none
};

// " %f" and " %d": what strtof and strtol would read, finite and in range.
template <typename T>
bool Reader::number(Values& values) {
    const size_t at = skipBlanks(), length = numberLength(text_.substr(at), std::is_floating_point_v<T>);
    std::string_view digits = text_.substr(at, length);
    if (digits.starts_with('+')) digits.remove_prefix(1);
    T value{};
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (length == 0 || ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(double(value)))
        return false;
    values.push_back({double(value), text_.substr(at, length), at});
    return pos_ += length, true;
}

bool Reader::convert(char kind, Values& values) {
    if (kind == 'f' || kind == 'd') return kind == 'f' ? number<float>(values) : number<int>(values);
    const size_t from = kind == 's' ? skipBlanks() : pos_;
    while (!atBlank() && (kind == 's' || pos_ == from)) ++pos_; // %s: a word; %c: one character
    if (pos_ > from) values.push_back({0.0, text_.substr(from, pos_ - from), from});
    return pos_ > from;
}

bool Reader::scan(std::string_view format, Values& values) {
    bool optional = false;
    for (size_t f = 0; f < format.size(); ++f) {
        if (format[f] == '|' || format[f] == ' ') {
            optional |= format[f] == '|';
            skipBlanks();
            continue;
        }
        const size_t at = pos_;
        const char kind = format[f] == '%' && f + 1 < format.size() ? format[++f] : '\0';
        if (kind ? convert(kind, values) : accept(format.substr(f, 1))) continue;
        if (optional) return pos_ = at, true;
        constexpr std::string_view kWhat[] = {"a number", "an integer", "a word", "a one-character id"};
        const std::string expected =
            kind ? std::string(kWhat[std::string_view("fdsc").find(kind)]) : shown(format.substr(f, 1));
        return fail(expected, skipBlanks()), false;
    }
    return true;
}

// What each label's values mean (cpfg's interpret.c, ReadViewData). A scale
// of 0 is 1, as cpfg sets it ("Initial scale cannot be 0! Set to 1.").
using V = ViewFile;
using Store = void (*)(Reader&, const Values&);
template <float ViewFile::*Field, bool kScale = false>
void numberInto(Reader& r, const Values& v) {
    r.view().*Field = kScale && v[0].number == 0.0 ? 1.0f : float(v[0].number);
}

// cpfg divides a direction by its length: 0 gives none.
template <glm::vec3 ViewFile::*Field, bool kDirection = false>
void vectorInto(Reader& r, const Values& v) {
    const glm::dvec3 vector(v[0].number, v[1].number, v[2].number); // a length in double does not overflow
    if (kDirection && glm::length(vector) == 0.0)
        return r.fail("a direction x,y,z other than 0,0,0", v[0].at, shown(r.label) + " has length 0");
    r.view().*Field = glm::vec3(kDirection ? glm::normalize(vector) : vector);
}

// "initial color: a [b]" and "color increment: a [b]": b, for back faces.
template <int ViewFile::*Front, std::optional<int> ViewFile::*Back>
void frontAndBack(Reader& r, const Values& v) {
    r.view().*Front = int(v[0].number);
    if (v.size() > 1) r.view().*Back = int(v[1].number);
}

void angleFactor(Reader& r, const Values& v) {
    if (v[0].number == 0.0) return r.fail("a number other than 0", v[0].at, "'angle factor:' of 0 makes no angle");
    r.view().angleIncrement = float(360.0 / v[0].number);
}

// A number alone means polygons; of a word after it cpfg reads the first letter: 'p' pixels, 's' cylinders.
void initialLineWidth(Reader& r, const Values& v) {
    const std::string_view unit = v.size() > 1 ? v[1].text : "";
    const bool pixels = unit.starts_with('p'), cylinders = unit.starts_with('s');
    r.view().initialLineWidth = float(v[0].number);
    r.view().lineStyle = pixels ? LineStyle::Pixel : cylinders ? LineStyle::Cylinder : LineStyle::Polygon;
    if (!unit.empty() && !pixels && !cylinders)
        r.warn("of " + shown(unit) + " cpfg reads only 'p' (pixels) or 's' (cylinders): these are polygons", v[1].at);
}

void lineStyle(Reader& r, const Values& v) {
    constexpr std::string_view kStyles[] = {"pixel", "polygon", "cylinder"};
    const auto* known = std::find(std::begin(kStyles), std::end(kStyles), v[0].text);
    // cpfg also takes "1", "2", "3" (of which it reads the first character).
    const int index = known != std::end(kStyles) ? int(known - kStyles) : v[0].text[0] - '1';
    if (index >= 0 && index < 3) r.view().lineStyle = static_cast<LineStyle>(index);
    if (index < 0 || index >= 3) r.warn("unknown line style " + shown(v[0].text) + ": the style stays", v[0].at);
}

void projection(Reader& r, const Values& v) {
    r.view().perspective = v[0].text.starts_with("perspective");
    if (!r.view().perspective && !v[0].text.starts_with("parallel"))
        r.warn("unknown projection " + shown(v[0].text) + ": parallel, as cpfg assumes", v[0].at);
}

void taperedLines(Reader& r, const Values& v) { r.view().taperedLines = v[0].text == "on"; }

// "contour sides: n", or the older "polygonization level: n" of 2^(n+1) sides.
template <bool kLevel>
void contourSides(Reader& r, const Values& v) {
    const int n = int(v[0].number);
    if (kLevel && n > 20) return r.fail("0 to 20", v[0].at, "a polygonization level over 20 makes too many sides");
    r.view().contourSides = std::max(kLevel ? (n < 1 ? 0 : 1 << (n + 1)) : n, 3);
}

// "surface: id file scale [s t] [texture]": the scale is 1 unless positive; one number alone is the texture.
void surface(Reader& r, const Values& v) {
    ViewSurface surface{std::string(v[0].text), std::string(v[1].text), v[2].number > 0.0 ? float(v[2].number) : 1};
    if (v[1].at == v[0].at + 1)
        r.warn("cpfg reads " + shown(surface.id) + " as the id and " + shown(v[1].text) + " as the file", v[0].at);
    if (v.size() > 4) surface.sPrecision = int(v[3].number), surface.tPrecision = int(v[4].number);
    surface.texture = v.size() == 4 ? int(v[3].number) : v.size() == 6 ? int(v[5].number) : -1;
    surface.line = r.labelLine();
    r.view().surfaces.push_back(std::move(surface));
}

void function(Reader& r, const Values& v) {
    r.view().functions.push_back({std::string(v[0].text), v.size() > 1 ? int(v[1].number) : -1, r.labelLine()});
    if (r.view().functionSet) r.view().functionSet->names = false;
}

// cpfg's ReadFunctionSet empties its table of functions first (splinefun.cpp).
void functionSet(Reader& r, const Values& v) {
    r.view().functions.clear();
    r.view().functionSet = ViewFunctionSet{std::string(v[0].text), r.labelLine()};
}

void contour(Reader& r, const Values& v) {
    r.view().contours.push_back({int(v[0].number), std::string(v[1].text), r.labelLine()});
}

// strtok over a line, as cpfg's read_movement and get_double call it: each
// call skips the delimiters it is given and returns what follows, up to the
// next one, with its offset in the line; empty at the end.
struct Tokens {
    std::string_view line;
    size_t pos = 0;
    std::pair<std::string_view, size_t> next(std::string_view delimiters) {
        while (pos < line.size() && delimiters.find(line[pos]) != std::string_view::npos) ++pos;
        const size_t from = pos;
        while (pos < line.size() && delimiters.find(line[pos]) == std::string_view::npos) ++pos;
        return {line.substr(from, pos - from), from};
    }
};

// "tropism: T: 0,1,0 A: 90 E: 0.2 S: 0.05" and "torque: T: ...": letters and
// their values as cpfg's read_movement reads them (movements.c): T a
// direction, I an intensity (the direction's length once normalised, kept
// within [-1, 1]; before T it is 0), A the angle γ in degrees, E the
// elasticity, S its step for @Ti and @Td. cpfg reads each number with atof
// (text that is no number is 0) and ignores a movement with an unknown
// letter, a zero direction or a zero intensity, or past the tenth: so is it
// here, with a warning.
template <MovementKind kind>
void movement(Reader& r, const Values&) {
    // Not a structured binding: the lambdas below capture lineStart, which
    // clang accepts of a binding only from version 16 (tools/fuzz.sh builds with clang 14).
    const std::pair<std::string_view, size_t> rest = r.restOfLine();
    const size_t lineStart = rest.second;
    Tokens tokens{rest.first};
    Movement movement{kind};
    glm::dvec3 direction(0.0, 1.0, 0.0);
    double scale = 0.0; // 1/|T|, times the intensity
    auto number = [&](double& value) {
        const auto [token, at] = tokens.next(" ,\t:");
        if (token.empty()) return r.fail("a number", lineStart + at, "a number is missing"), false;
        const size_t length = numberLength(token, true);
        value = length == 0 ? 0.0 : std::strtod(std::string(token.substr(0, length)).c_str(), nullptr);
        return true;
    };
    auto ignored = [&](std::string why, size_t at) {
        r.warn(why + ": cpfg ignores this " + std::string(r.label.substr(0, r.label.size() - 1)), lineStart + at);
    };
    for (auto [token, at] = tokens.next(" \t:"); !token.empty(); std::tie(token, at) = tokens.next(" \t:")) {
        double value = 0.0;
        switch (token[0]) {
        case 'T':
            if (!number(direction.x) || !number(direction.y) || !number(direction.z)) return;
            if (glm::dot(direction, direction) == 0.0) return ignored("a zero direction", at);
            scale = 1.0 / glm::length(direction);
            break;
        case 'I':
            if (!number(value)) return;
            scale = std::clamp(scale * value, -1.0, 1.0);
            if (scale == 0.0) return ignored("a zero intensity (or one before the direction)", at);
            break;
        case 'A':
        case 'E':
        case 'S':
            if (!number(value)) return;
            (token[0] == 'A'   ? movement.angle
             : token[0] == 'E' ? movement.elasticity
                               : movement.increment) = float(value);
            break;
        default: return ignored("an unknown letter " + shown(token.substr(0, 1)) + " (T, I, A, E or S)", at);
        }
    }
    if (r.view().movements.size() == kMaxMovements)
        return ignored("more than " + std::to_string(kMaxMovements) + " tropisms and torques", 0);
    movement.direction = glm::vec3(direction * scale);
    r.view().movements.push_back(movement);
}

void box(Reader& r, const Values& v) {
    r.view().box = ViewBox{{v[0].number, v[2].number, v[4].number}, {v[1].number, v[3].number, v[5].number}};
}

// "# 12 "file"" or "#line 12 "file"", cpp's line markers (flags after the name skipped).
void lineMarker(Reader& r, const Values& v) {
    if (v[0].number < 1 || v[0].number > 1e8) return r.fail("1 to 10^8", v[0].at, "line out of range");
    std::string_view name = v.size() > 1 ? v[1].text : "";
    if (name.size() >= 2 && name.starts_with('"') && name.ends_with('"')) name = name.substr(1, name.size() - 2);
    r.setMarker(int(v[0].number), name);
    r.skipLine();
}

struct LabelFormat {
    std::string_view label, format; // cpfg's label and fscanf format
    Store store;
    std::string_view example; // values, for error messages
};

// cpfg's table of labels (interpret.c, ReadViewData): those read here,
constexpr LabelFormat kRead[] = {
    {"angle factor:", " %f", angleFactor, "8"},
    {"angle increment:", " %f", numberInto<&V::angleIncrement>, "22.5"},
    {"initial color:", " %d| %d", frontAndBack<&V::initialColor, &V::initialBackColor>, "1 [2]"},
    {"color increment:", " %d| %d", frontAndBack<&V::colorIncrement, &V::backColorIncrement>, "1 [1]"},
    {"initial line width:", " %f| %s", initialLineWidth, "2 pixels"},
    {"line width increment:", " %f", numberInto<&V::lineWidthIncrement>, "0.5"},
    {"viewpoint:", " %f,%f,%f", vectorInto<&V::viewpoint>, "0,0,1"},
    {"view reference point:", " %f,%f,%f", vectorInto<&V::viewReferencePoint>, "0,0,0"},
    {"twist:", " %d", numberInto<&V::twist>, "0"},
    {"projection:", " %s", projection, "parallel"},
    {"scale factor:", " %f", numberInto<&V::zoom, true>, "0.9"},
    {"light direction:", " %f,%f,%f", vectorInto<&V::lightDirection, true>, "1,1,1"},
    {"surface:", " %c %s %f| %d %d %d", surface, "l leaf.s 1.0 8 4"},
    {"box:", " x: %f,%f y: %f,%f z: %f,%f", box, "x: -1,1 y: 0,2 z: -1,1"},
    {"#", " %d| %s", lineMarker, "12 \"plant.v\""},
    {"polygonization level:", " %d", contourSides<true>, "3"},
    {"tropism direction:", " %f,%f,%f", vectorInto<&V::tropismDirection, true>, "0,-1,0"},
    {"tropism:", "", movement<MovementKind::Tropism>, "T: 0,-1,0 A: 0 E: 0.2"},
    {"torque:", "", movement<MovementKind::Twist>, "T: 0,1,0 E: 0.1"},
    {"initial elasticity:", " %f", numberInto<&V::initialElasticity>, "0.1"},
    {"elasticity increment:", " %f", numberInto<&V::elasticityIncrement>, "0.05"},
    {"line style:", " %s", lineStyle, "cylinder"},
    {"tapered lines:", " %s", taperedLines, "on"},
    {"contour sides:", " %d", contourSides<false>, "8"},
    {"contour:", "%d %s", contour, "1 leaf.con"},
    {"viewing angle:", " %f", numberInto<&V::viewingAngle>, "45"},
    {"initial scale:", " %f", numberInto<&V::initialScale, true>, "1"},
    {"scale multiplier:", " %f", numberInto<&V::scaleMultiplier, true>, "0.9"},
    {"function:", " %s| %d", function, "internode.func 100"},
    {"function set:", " %s", functionSet, "functions.fset"}};
// those of cpfg's window and renderer, accepted quietly (one per line),
constexpr std::string_view kQuiet = "\nfront distance:\nback distance:\nz buffer:\ncue range:\nshade mode:\n"
                                    "diffuse reflection:\nsurface ambient:\nsurface diffuse:\nbackground color:\n"
                                    "ambient light:\nfont:\nlight:\nrender mode:\ntwist of cylinders:\n"
                                    "interpretation step:\ninterpretation past %:\nrayshade objects:\n"
                                    "rayshade scale:\nenvironment display:\nantialiasing:\nmin zoom:\nmax zoom:\n"
                                    "generate on view change:\nwinfont:\nconcave polygons:\nshadow map:\nPS linecap:\n";
// and those whose absence changes the plant: read, but not drawn (warned of).
constexpr std::string_view kNotDrawn = "\nline:\nblob:\ntexture:\nbackground scene:\ntsurface:\n"
                                       "curve:\n";

bool listed(std::string_view list, std::string_view label) {
    return list.find(std::string("\n").append(label) + "\n") != std::string_view::npos;
}

// Reads the values of a label of cpfg's; false for a label cpfg does not know.
bool readLabel(Reader& r, std::string_view label) {
    r.label = label;
    for (const LabelFormat& entry : kRead) {
        if (entry.label != label) continue;
        r.example = entry.example;
        if (label == "#") r.accept("line"); // "#line 12 "file"" too
        Values values;
        if (r.scan(entry.format, values)) entry.store(r, values);
        return true;
    }
    const bool notDrawn = listed(kNotDrawn, label);
    if (notDrawn) r.warn(shown(label) + " is not supported: the plant is drawn without it");
    r.skipLine();
    return notDrawn || listed(kQuiet, label);
}

void Reader::run() {
    if (const size_t nul = text_.find('\0'); nul != std::string_view::npos)
        add(result.diagnostics, nul, "a NUL byte: a view file is text", {});
    while (true) {
        // cpfg skips spaces and newlines before a label (and Windows' text
        // mode the '\r' of "\r\n"), but not tabs.
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\r')) ++pos_;
        if (pos_ == text_.size()) return;
        labelStart_ = pos_;
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != ':' && text_[pos_] != '#') ++pos_;
        if (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        const std::string_view text = text_.substr(labelStart_, pos_ - labelStart_);
        if (std::all_of(text.begin(), text.end(), isBlank) || readLabel(*this, text)) continue;
        warn("unknown label " + shown(text) + ": cpfg matches labels exactly and skips the rest of the line");
    }
}

} // namespace

ViewReadResult parseViewFile(std::string_view text, const std::string& file) {
    const std::string clean = withoutComments(text);
    Reader reader(clean, file);
    reader.run();
    return std::move(reader.result);
}

ViewReadResult readViewFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::vector<Diagnostic> unread;
    const std::optional<std::string> text = readTextFileOf("view", path, kMaxViewFileBytes, unread);
    if (!text) return {{}, std::move(unread), {}};
    // Binary is not given to the preprocessor, which would drop its NUL bytes.
    if (text->find('\0') != std::string::npos) return parseViewFile(*text, name);
    const PreprocessedText preprocessed = runCPreprocessor(*text, name, {});
    if (!preprocessed.diagnostics.empty()) return {{}, preprocessed.diagnostics, {}};
    ViewReadResult result = parseViewFile(preprocessed.text, name);
    mapToFiles(preprocessed, result.diagnostics);
    mapToFiles(preprocessed, result.warnings);
    auto mapLine = [&](int& line) { // to the line of the file it came from
        if (line >= 1 && size_t(line) <= preprocessed.lines.size()) line = preprocessed.lines[size_t(line) - 1].line;
    };
    for (ViewSurface& surface : result.view.surfaces) mapLine(surface.line);
    for (ViewFunction& function : result.view.functions) mapLine(function.line);
    for (ViewContour& contour : result.view.contours) mapLine(contour.line);
    if (result.view.functionSet) mapLine(result.view.functionSet->line);
    return result;
}

} // namespace lsys::vlab
