// Checked reading of a JSON file, shared by the scene loader (engine/scene),
// component plants (lsystem/components) and ramification trees
// (lsystem/ramification/ramification_file.h): every value carries its JSON
// pointer, and every error names the file, the line and column of the value at
// fault and what was expected. Needs nlohmann_json (linked privately by the
// library; its users link it themselves).
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"

namespace lsys {

// Every problem in a JSON document: what() is "file:line:column: /json/pointer
// message" (or "file: message" when the file as a whole is at fault, line 0);
// `diagnostic` holds the same parts, for readers that report lsys::Diagnostics
// with the offending line under them (formatDiagnostics).
struct JsonError : std::runtime_error {
    explicit JsonError(Diagnostic diagnostic);
    Diagnostic diagnostic;
};

// What kind of document a file is, for messages ("the scene file is larger
// than 256 MiB", "the scene must be an object"), its size limit and how deep
// its arrays and objects may nest. Text nesting deeper is refused at the
// bracket that opens one level too many, before it is parsed: the format's
// shape is known, so deeper text is a mistake, and nlohmann::json's dump and
// comparisons recurse as deep as a value nests.
struct JsonDocumentKind {
    std::string name;
    size_t maxBytes = 0;
    uint32_t maxDepth = 64; // past any of our formats' shapes
};

// The parsed document and the text it came from, for locating values.
struct JsonSource {
    std::filesystem::path file;
    std::string text;
    nlohmann::json root;
    std::string kind; // JsonDocumentKind::name
};

// Throws JsonError when the file cannot be read, is not JSON, nests deeper
// than kind.maxDepth or repeats a key in one object; MemoryBudgetError (stage
// "KIND file") when the parsed document would not fit `memory`, judged from
// the text before parsing it.
JsonSource readJsonFile(const std::filesystem::path& file, const JsonDocumentKind& kind,
                        const MemoryBudget& memory = {});
// At most what parsing `text` takes: the text, and nlohmann::json's values,
// objects, members, arrays and strings, counted in one scan of it.
uint64_t parsedJsonBytes(std::string_view text);
// The same for text already read (kind.maxBytes is not checked); `file`
// names it in errors.
JsonSource parseJsonText(std::string text, const std::filesystem::path& file, const JsonDocumentKind& kind);

// One value of a document and the path of keys and indices leading to it.
struct JsonNode {
    const JsonSource* source = nullptr;
    const nlohmann::json* value = nullptr;
    std::vector<std::string> path;

    std::string pointer() const; // RFC 6901, e.g. /species/2/density
};

JsonNode rootNode(const JsonSource& source);

// Where the value (or, with atKey, its key) starts: "file:line:column".
std::string locationOf(const JsonNode& node, bool atKey = false);

// "file:line:column" of every member's value of an object, by key, found in
// one walk of the text (locationOf for each member would walk the text again
// for each: quadratic in a large object). Empty when node is no object.
std::map<std::string, std::string, std::less<>> memberLocations(const JsonNode& object);

// JsonError("file:line:column: /pointer message").
[[noreturn]] void failAt(const JsonNode& node, std::string_view message, bool atKey = false);

// Checks that node is an object whose keys are all in known; an unknown key is
// an error suggesting the closest known one.
void requireObject(const JsonNode& node, std::initializer_list<std::string_view> known);
// Checks that node is an object whose keys are names the caller checks itself.
void requireMap(const JsonNode& node);
std::optional<JsonNode> member(const JsonNode& object, std::string_view key);
JsonNode requireMember(const JsonNode& object, std::string_view key, std::string_view expected);
std::vector<JsonNode> arrayElements(const JsonNode& node, std::string_view expected);

// Allowed numbers: [min, max] with either end open. Values are stored as
// float, so the widest range is float's.
struct Range {
    double min = std::numeric_limits<float>::lowest();
    double max = std::numeric_limits<float>::max();
    bool minOpen = false;
    bool maxOpen = false;
};
Range anyNumber();
Range atLeast(double min);
Range above(double min);
Range between(double min, double max);

double readNumber(const JsonNode& node, Range range);
// Whole numbers ≥ 0 (a negative one is out of range): readInteger up to
// 2^32 − 1, readInteger64 up to 2^64 − 1 (seeds, budgets).
uint32_t readInteger(const JsonNode& node, Range range);
uint64_t readInteger64(const JsonNode& node, Range range);
std::string readString(const JsonNode& node);
// An array of exactly N numbers, each in range.
template <int N>
glm::vec<N, float> readVector(const JsonNode& node, Range range);

// The same, reading object[key] into out when it is there and leaving out
// (the default) alone when it is not.
void readField(const JsonNode& object, std::string_view key, float& out, Range range);
void readField(const JsonNode& object, std::string_view key, double& out, Range range);
void readField(const JsonNode& object, std::string_view key, uint32_t& out, Range range);
void readField(const JsonNode& object, std::string_view key, uint64_t& out, Range range);
void readField(const JsonNode& object, std::string_view key, std::optional<float>& out, Range range);
void readField(const JsonNode& object, std::string_view key, std::optional<uint32_t>& out, Range range);
void readField(const JsonNode& object, std::string_view key, glm::vec2& out, Range range);
void readField(const JsonNode& object, std::string_view key, glm::vec3& out, Range range);
void readField(const JsonNode& object, std::string_view key, std::string& out);
void readField(const JsonNode& object, std::string_view key, bool& out);

// "; did you mean \"x\"?" for the known word x closest to word, or empty when
// none is close enough to be a typo.
std::string didYouMean(std::string_view word, const std::vector<std::string_view>& known);

} // namespace lsys
