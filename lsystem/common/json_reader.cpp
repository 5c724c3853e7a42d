#include "lsystem/common/json_reader.h"

#include "lsystem/common/file_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>

namespace lsys {
namespace {

// ---- locating a value in the text -----------------------------------------
// nlohmann::json keeps no source positions, so a value's position is found by
// walking the (already valid) text along the node's path. Every step is
// bounds-checked: a position past the end means "not found", never a crash.

size_t skipSpace(std::string_view text, size_t pos) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\n' || text[pos] == '\r'))
        ++pos;
    return pos;
}

size_t skipString(std::string_view text, size_t pos) {
    for (++pos; pos < text.size() && text[pos] != '"'; ++pos)
        if (text[pos] == '\\') ++pos;
    return std::min(pos + 1, text.size());
}

size_t skipValue(std::string_view text, size_t pos) {
    if (pos >= text.size()) return pos;
    if (text[pos] == '"') return skipString(text, pos);
    if (text[pos] != '{' && text[pos] != '[') {
        while (pos < text.size() && !std::strchr(",]} \t\r\n", text[pos])) ++pos;
        return pos;
    }
    int depth = 0;
    while (pos < text.size()) {
        const char c = text[pos];
        if (c == '"') {
            pos = skipString(text, pos);
            continue;
        }
        ++pos;
        if (c == '{' || c == '[') ++depth;
        if ((c == '}' || c == ']') && --depth == 0) return pos;
    }
    return pos;
}

// After a value at pos: past the following comma, at the next entry.
size_t nextEntry(std::string_view text, size_t pos) {
    pos = skipSpace(text, skipValue(text, pos));
    return pos < text.size() && text[pos] == ',' ? skipSpace(text, pos + 1) : text.size();
}

std::string decodeKey(std::string_view quoted) {
    try {
        return nlohmann::json::parse(quoted).get<std::string>();
    } catch (const nlohmann::json::exception&) {
        return {};
    }
}

struct Located {
    size_t keyOffset;
    size_t valueOffset;
};

Located locate(std::string_view text, const std::vector<std::string>& path) {
    size_t pos = skipSpace(text, text.starts_with("\xEF\xBB\xBF") ? 3 : 0); // nlohmann skips a UTF-8 BOM too
    Located found{pos, pos};
    for (const std::string& token : path) {
        if (pos >= text.size()) break;
        if (text[pos] == '{') {
            pos = skipSpace(text, pos + 1);
            while (pos < text.size() && text[pos] == '"') {
                const size_t keyStart = pos;
                const size_t keyEnd = skipString(text, pos);
                pos = skipSpace(text, keyEnd);
                pos = skipSpace(text, pos + 1); // past ':'
                if (decodeKey(text.substr(keyStart, keyEnd - keyStart)) == token) {
                    found = {keyStart, pos};
                    break;
                }
                pos = nextEntry(text, pos);
            }
        } else if (text[pos] == '[') {
            pos = skipSpace(text, pos + 1);
            for (unsigned long i = std::strtoul(token.c_str(), nullptr, 10); i > 0 && pos < text.size(); --i)
                pos = nextEntry(text, pos);
            found = {pos, pos};
        }
        if (found.valueOffset != pos) break; // not found: report the enclosing value
    }
    return found;
}

// A diagnostic at offset in text, its 1-based line and column counted in bytes.
Diagnostic diagnosticAt(const std::filesystem::path& file, std::string_view text, size_t offset, std::string message) {
    offset = std::min(offset, text.size());
    const std::string_view before = text.substr(0, offset);
    const size_t lineStart = before.rfind('\n');
    Diagnostic diagnostic;
    diagnostic.file = file.string();
    diagnostic.line = 1 + int(std::count(before.begin(), before.end(), '\n'));
    diagnostic.column = int(offset - (lineStart == std::string_view::npos ? 0 : lineStart + 1)) + 1;
    diagnostic.message = std::move(message);
    return diagnostic;
}

// The file as a whole at fault (line 0): it cannot be read, it is too large.
[[noreturn]] void failFile(const std::filesystem::path& file, std::string message) {
    Diagnostic diagnostic;
    diagnostic.file = file.string();
    diagnostic.message = std::move(message);
    throw JsonError(std::move(diagnostic));
}

// ---- messages -------------------------------------------------------------

std::string formatNumber(double value) {
    // Whole numbers in full (10000000, not 1e+07); others in the shortest form.
    if (value == std::floor(value) && std::abs(value) < 1e15) return std::to_string(int64_t(value));
    std::ostringstream out;
    out << value;
    return out.str();
}

// typeMax: the largest value the reader's type holds; a bound at or past it is
// the type's, not the format's, and goes unsaid.
std::string describe(Range range, double typeMax = double(std::numeric_limits<uint32_t>::max())) {
    const bool hasMin = range.min != std::numeric_limits<float>::lowest();
    const bool hasMax = range.max < typeMax;
    if (hasMin && hasMax)
        return std::string(" in ") + (range.minOpen ? "(" : "[") + formatNumber(range.min) + ", " +
               formatNumber(range.max) + (range.maxOpen ? ")" : "]");
    if (hasMin) return (range.minOpen ? " > " : " ≥ ") + formatNumber(range.min);
    return "";
}

// The value as the file writes it, on one line and cut short. Read from the
// text rather than dumped, since dumping recurses as deep as the value nests.
std::string shown(const JsonNode& node) {
    const std::string_view text = node.source->text;
    const size_t start = locate(text, node.path).valueOffset;
    std::string written(text.substr(start, std::min<size_t>(skipValue(text, start) - start, 40)));
    std::replace_if(
        written.begin(), written.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
    return written.size() == 40 ? written.substr(0, 37) + "..." : written;
}

[[noreturn]] void failExpected(const JsonNode& node, const std::string& expected) {
    failAt(node, "must be " + expected + " (got " + shown(node) + ")");
}

bool inRange(double value, Range range) {
    if (!std::isfinite(value)) return false;
    const bool aboveMin = range.minOpen ? value > range.min : value >= range.min;
    const bool belowMax = range.maxOpen ? value < range.max : value <= range.max;
    return aboveMin && belowMax;
}

// Past the longest key or name any of our formats has.
constexpr size_t kMaxSuggestedLength = 64;

size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitution =
                diagonal + (std::tolower((unsigned char)a[i - 1]) != std::tolower((unsigned char)b[j - 1]));
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

// The offset of the first key an object repeats, or npos. nlohmann::json
// keeps the last value while positions are looked up at the first, so a
// repeated key would be reported at the wrong place with the wrong value.
size_t repeatedKeyOffset(std::string_view text, std::string& key) {
    struct Level {
        bool object = false;
        bool expectKey = false;
        std::set<std::string_view> keys;
    };
    std::vector<Level> levels;
    for (size_t pos = 0; pos < text.size();) {
        const char c = text[pos];
        if (c == '"') {
            const size_t end = skipString(text, pos);
            if (!levels.empty() && levels.back().expectKey) {
                const std::string_view raw = text.substr(pos, end - pos);
                if (!levels.back().keys.insert(raw).second) {
                    key = decodeKey(raw);
                    return pos;
                }
                levels.back().expectKey = false;
            }
            pos = end;
            continue;
        }
        if (c == '{' || c == '[')
            levels.push_back({c == '{', c == '{', {}});
        else if ((c == '}' || c == ']') && !levels.empty())
            levels.pop_back();
        else if (c == ',' && !levels.empty() && levels.back().object)
            levels.back().expectKey = true;
        ++pos;
    }
    return std::string_view::npos;
}

// The offset of the bracket that first opens more than maxDepth arrays or
// objects, or npos. A scan of the text, not a parse: it runs first, so that
// it holds for text nlohmann::json would refuse only at its end.
size_t tooDeepOffset(std::string_view text, uint32_t maxDepth) {
    uint32_t depth = 0;
    for (size_t pos = 0; pos < text.size();) {
        const char c = text[pos];
        if (c == '"') {
            pos = skipString(text, pos);
            continue;
        }
        if ((c == '[' || c == '{') && ++depth > maxDepth) return pos;
        if ((c == ']' || c == '}') && depth > 0) --depth;
        ++pos;
    }
    return std::string_view::npos;
}

template <typename Unsigned>
Unsigned readUnsigned(const JsonNode& node, Range range) {
    const double typeMax = double(std::numeric_limits<Unsigned>::max());
    range.min = std::max(range.min, 0.0);
    range.max = std::min(range.max, typeMax);
    if (!node.value->is_number_integer() || !inRange(node.value->get<double>(), range))
        failExpected(node, "an integer" + describe(range, typeMax));
    return node.value->get<Unsigned>();
}

JsonNode childNode(const JsonNode& parent, const nlohmann::json& value, std::string token) {
    JsonNode child{parent.source, &value, parent.path};
    child.path.push_back(std::move(token));
    return child;
}

} // namespace

JsonError::JsonError(Diagnostic located)
    : std::runtime_error(located.file +
                         (located.line > 0 ? ":" + std::to_string(located.line) + ":" + std::to_string(located.column)
                                           : std::string()) +
                         ": " + located.message),
      diagnostic(std::move(located)) {}

uint64_t parsedJsonBytes(std::string_view text) {
    uint64_t objects = 0, arrays = 0, members = 0, commas = 0, strings = 0;
    for (size_t pos = 0; pos < text.size();) {
        const char c = text[pos];
        if (c == '"') {
            ++strings;
            pos = skipString(text, pos);
            continue;
        }
        objects += c == '{';
        arrays += c == '[';
        members += c == ':';
        commas += c == ',';
        ++pos;
    }
    // Every value follows a comma or opens its container (or is the root).
    const uint64_t values = commas + objects + arrays + 1;
    // A heap block's own bookkeeping; a std::map node's links and colour.
    constexpr uint64_t kAllocation = 16, kMapNode = 32;
    // Values twice: an array's vector grows to up to twice its elements.
    const uint64_t valueBytes = values * 2 * sizeof(nlohmann::json);
    const uint64_t objectBytes = objects * (sizeof(nlohmann::json::object_t) + kAllocation);
    const uint64_t arrayBytes = arrays * (sizeof(nlohmann::json::array_t) + kAllocation);
    // A member: its map node with the key and value, and the key again in
    // the parse's check for repeated keys (a set of the object's keys).
    const uint64_t memberBytes =
        members * (kMapNode + sizeof(std::string) + sizeof(nlohmann::json) + kAllocation + kMapNode + 16 + kAllocation);
    const uint64_t stringBytes = strings * (sizeof(std::string) + kAllocation);
    // The text, and its characters again in the strings and keys parsed from it.
    return bytesPlus(bytesTimes(text.size(), 2), bytesPlus(bytesPlus(valueBytes, objectBytes),
                                                           bytesPlus(bytesPlus(arrayBytes, memberBytes), stringBytes)));
}

JsonSource readJsonFile(const std::filesystem::path& file, const JsonDocumentKind& kind, const MemoryBudget& memory) {
    FileBytes read = readFileUpTo(file, kind.maxBytes);
    if (read.problem != FileProblem::None)
        failFile(file, "the " + kind.name + " file " + fileProblemText(read.problem, kind.maxBytes));
    try {
        need(memory, kind.name + " file", parsedJsonBytes(read.bytes));
    } catch (const MemoryBudgetError& error) {
        throw MemoryBudgetError(file.string() + ": " + error.what());
    }
    return parseJsonText(std::move(read.bytes), file, kind);
}

JsonSource parseJsonText(std::string text, const std::filesystem::path& file, const JsonDocumentKind& kind) {
    JsonSource source{file, std::move(text), {}, kind.name};
    const auto fail = [&](size_t offset, std::string message) {
        throw JsonError(diagnosticAt(file, source.text, offset, std::move(message)));
    };
    if (const size_t deep = tooDeepOffset(source.text, kind.maxDepth); deep != std::string_view::npos)
        fail(deep, "the " + kind.name + " nests deeper than " + std::to_string(kind.maxDepth) + " levels");
    try {
        source.root = nlohmann::json::parse(source.text);
    } catch (const nlohmann::json::out_of_range& e) {
        // A number too large for a double ("number overflow parsing '1e999'")
        // carries no position: find the literal the message quotes.
        const std::string what = e.what();
        const size_t open = what.find('\''), close = what.rfind('\'');
        const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : std::string();
        const size_t offset = literal.empty() ? std::string::npos : source.text.find(literal);
        fail(offset == std::string::npos ? 0 : offset, "a number too large: " + literal);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is the 1-based offset of the last character read; the
        // message after "column N: " says what was wrong there.
        std::string what = e.what();
        const size_t column = what.find("column ");
        const size_t detail = what.find(": ", column == std::string::npos ? 0 : column);
        if (detail != std::string::npos) what = what.substr(detail + 2);
        fail(e.byte > 0 ? e.byte - 1 : 0, what);
    }
    std::string key;
    if (const size_t repeated = repeatedKeyOffset(source.text, key); repeated != std::string_view::npos)
        fail(repeated, "\"" + key + "\" is given twice in one object");
    return source;
}

std::string JsonNode::pointer() const {
    std::string text;
    for (const std::string& token : path) {
        text += '/';
        for (char c : token) text += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    }
    return text;
}

JsonNode rootNode(const JsonSource& source) { return {&source, &source.root, {}}; }

namespace {

Diagnostic diagnosticOf(const JsonNode& node, bool atKey, std::string message) {
    const Located at = locate(node.source->text, node.path);
    return diagnosticAt(node.source->file, node.source->text, atKey ? at.keyOffset : at.valueOffset,
                        std::move(message));
}

} // namespace

std::string locationOf(const JsonNode& node, bool atKey) {
    const Diagnostic at = diagnosticOf(node, atKey, {});
    return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

std::map<std::string, std::string, std::less<>> memberLocations(const JsonNode& object) {
    std::map<std::string, std::string, std::less<>> locations;
    const std::string_view text = object.source->text;
    size_t pos = locate(text, object.path).valueOffset;
    if (!object.value->is_object() || pos >= text.size() || text[pos] != '{') return locations;
    // Lines counted on from the last member, not from the start each time.
    size_t counted = 0, lineStart = 0;
    int line = 1;
    const std::string file = object.source->file.string();
    for (pos = skipSpace(text, pos + 1); pos < text.size() && text[pos] == '"'; pos = nextEntry(text, pos)) {
        const size_t keyEnd = skipString(text, pos);
        const std::string key = decodeKey(text.substr(pos, keyEnd - pos));
        pos = skipSpace(text, skipSpace(text, keyEnd) + 1); // past ':'
        for (; counted < pos; ++counted)
            if (text[counted] == '\n') {
                ++line;
                lineStart = counted + 1;
            }
        locations.emplace(key, file + ":" + std::to_string(line) + ":" + std::to_string(pos - lineStart + 1));
    }
    return locations;
}

void failAt(const JsonNode& node, std::string_view message, bool atKey) {
    const std::string where = node.path.empty() ? "the " + node.source->kind : node.pointer();
    throw JsonError(diagnosticOf(node, atKey, where + " " + std::string(message)));
}

void requireMap(const JsonNode& node) {
    if (!node.value->is_object()) failExpected(node, "an object");
}

void requireObject(const JsonNode& node, std::initializer_list<std::string_view> known) {
    requireMap(node);
    const std::vector<std::string_view> knownKeys(known);
    for (const auto& [key, value] : node.value->items()) {
        if (std::find(knownKeys.begin(), knownKeys.end(), key) != knownKeys.end()) continue;
        std::string hint = didYouMean(key, knownKeys);
        if (hint.empty()) {
            for (std::string_view k : knownKeys)
                hint += (hint.empty() ? " (expected one of \"" : ", \"") + std::string(k) + "\"";
            hint += ")";
        }
        failAt(childNode(node, value, key), "is an unknown key" + hint, true);
    }
}

std::optional<JsonNode> member(const JsonNode& object, std::string_view key) {
    const auto it = object.value->find(key);
    if (it == object.value->end()) return std::nullopt;
    return childNode(object, *it, std::string(key));
}

JsonNode requireMember(const JsonNode& object, std::string_view key, std::string_view expected) {
    if (std::optional<JsonNode> node = member(object, key)) return *node;
    failAt(object, "needs \"" + std::string(key) + "\": " + std::string(expected));
}

std::vector<JsonNode> arrayElements(const JsonNode& node, std::string_view expected) {
    if (!node.value->is_array()) failExpected(node, std::string(expected));
    std::vector<JsonNode> elements;
    for (size_t i = 0; i < node.value->size(); ++i)
        elements.push_back(childNode(node, (*node.value)[i], std::to_string(i)));
    return elements;
}

Range anyNumber() { return {}; }
Range atLeast(double min) { return {.min = min}; }
Range above(double min) { return {.min = min, .minOpen = true}; }
Range between(double min, double max) { return {.min = min, .max = max}; }

double readNumber(const JsonNode& node, Range range) {
    if (!node.value->is_number() || !inRange(node.value->get<double>(), range))
        failExpected(node, "a number" + describe(range, std::numeric_limits<float>::max()));
    return node.value->get<double>();
}

uint32_t readInteger(const JsonNode& node, Range range) { return readUnsigned<uint32_t>(node, range); }
uint64_t readInteger64(const JsonNode& node, Range range) { return readUnsigned<uint64_t>(node, range); }

std::string readString(const JsonNode& node) {
    if (!node.value->is_string()) failExpected(node, "a string");
    return node.value->get<std::string>();
}

template <int N>
glm::vec<N, float> readVector(const JsonNode& node, Range range) {
    const std::string expected = "an array of " + std::to_string(N) + " numbers" + describe(range);
    if (!node.value->is_array() || node.value->size() != N) failExpected(node, expected);
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i) {
        const nlohmann::json& component = (*node.value)[i];
        if (!component.is_number() || !inRange(component.get<double>(), range)) failExpected(node, expected);
        v[i] = component.get<float>();
    }
    return v;
}
template glm::vec2 readVector<2>(const JsonNode&, Range);
template glm::vec3 readVector<3>(const JsonNode&, Range);

void readField(const JsonNode& object, std::string_view key, float& out, Range range) {
    if (auto node = member(object, key)) out = float(readNumber(*node, range));
}
void readField(const JsonNode& object, std::string_view key, double& out, Range range) {
    if (auto node = member(object, key)) out = readNumber(*node, range);
}
void readField(const JsonNode& object, std::string_view key, uint32_t& out, Range range) {
    if (auto node = member(object, key)) out = readInteger(*node, range);
}
void readField(const JsonNode& object, std::string_view key, uint64_t& out, Range range) {
    if (auto node = member(object, key)) out = readInteger64(*node, range);
}
void readField(const JsonNode& object, std::string_view key, std::optional<float>& out, Range range) {
    if (auto node = member(object, key)) out = float(readNumber(*node, range));
}
void readField(const JsonNode& object, std::string_view key, std::optional<uint32_t>& out, Range range) {
    if (auto node = member(object, key)) out = readInteger(*node, range);
}
void readField(const JsonNode& object, std::string_view key, glm::vec2& out, Range range) {
    if (auto node = member(object, key)) out = readVector<2>(*node, range);
}
void readField(const JsonNode& object, std::string_view key, glm::vec3& out, Range range) {
    if (auto node = member(object, key)) out = readVector<3>(*node, range);
}
void readField(const JsonNode& object, std::string_view key, std::string& out) {
    if (auto node = member(object, key)) out = readString(*node);
}
void readField(const JsonNode& object, std::string_view key, bool& out) {
    if (auto node = member(object, key)) {
        if (!node->value->is_boolean()) failExpected(*node, "true or false");
        out = node->value->get<bool>();
    }
}

std::string didYouMean(std::string_view word, const std::vector<std::string_view>& known) {
    // A typo changes a few characters: allow 2 edits, more in long words.
    // The edit distance takes the product of the lengths, so words past
    // kMaxSuggestedLength (names no one types, from a generated or hostile
    // file) get no suggestion, and a candidate whose length alone differs by
    // too many edits is not measured: the cost stays bounded per candidate.
    if (word.size() > kMaxSuggestedLength) return "";
    size_t best = std::max<size_t>(2, word.size() / 3) + 1;
    std::string closest;
    for (std::string_view candidate : known) {
        const size_t lengthDifference =
            candidate.size() > word.size() ? candidate.size() - word.size() : word.size() - candidate.size();
        if (lengthDifference >= best) continue;
        const size_t distance = editDistance(word, candidate);
        if (distance < best) {
            best = distance;
            closest = candidate;
        }
    }
    return closest.empty() ? "" : "; did you mean \"" + closest + "\"?";
}

} // namespace lsys
