#include "lsystem/ramification_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lsystem/file_reader.h"

namespace lsys {

namespace {

// A matrix of kMaxRamificationOrders rows is about 40 KiB of JSON.
constexpr size_t kMaxRamificationFileBytes = size_t(1) << 20;

// Where each value (and each object member's key) of a document starts,
// by JSON pointer ("/p/2/0"). nlohmann::json keeps no positions, so the
// text, already parsed, is walked again.
struct JsonPositions {
    std::map<std::string, size_t> values, keys;
};

size_t skipJsonSpace(const std::string& text, size_t pos) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\n' || text[pos] == '\r'))
        ++pos;
    return pos;
}

// Past the string starting at pos (its opening quote).
size_t skipJsonString(const std::string& text, size_t pos) {
    for (++pos; pos < text.size() && text[pos] != '"'; ++pos)
        if (text[pos] == '\\') ++pos;
    return pos + 1;
}

size_t recordValue(const std::string& text, size_t pos, const std::string& pointer, JsonPositions& positions) {
    pos = skipJsonSpace(text, pos);
    positions.values[pointer] = pos;
    const char open = pos < text.size() ? text[pos] : '\0';
    if (open == '"') return skipJsonString(text, pos);
    if (open != '{' && open != '[') {
        while (pos < text.size() && !std::strchr(",]} \t\r\n", text[pos])) ++pos;
        return pos;
    }
    const char close = open == '{' ? '}' : ']';
    pos = skipJsonSpace(text, pos + 1);
    for (size_t index = 0; pos < text.size() && text[pos] != close; ++index) {
        std::string child = pointer + "/" + std::to_string(index);
        if (open == '{') {
            const size_t end = skipJsonString(text, pos);
            child = pointer + "/" + text.substr(pos + 1, end - pos - 2); // the keys read here need no escapes
            positions.keys[child] = pos;
            pos = skipJsonSpace(text, end) + 1; // the ':'
        }
        pos = skipJsonSpace(text, recordValue(text, pos, child, positions));
        if (pos < text.size() && text[pos] == ',') pos = skipJsonSpace(text, pos + 1);
    }
    return pos + 1;
}

// A .ram.json file nests 3 levels (the object, 'p', its rows); the walk
// above recurses, so deeper text is refused before it is parsed.
constexpr int kMaxJsonDepth = 8;

// Where the text first opens more than kMaxJsonDepth arrays or objects, or npos.
size_t tooDeepOffset(const std::string& text) {
    int depth = 0;
    for (size_t pos = 0; pos < text.size(); ++pos) {
        const char c = text[pos];
        if (c == '"')
            pos = skipJsonString(text, pos) - 1;
        else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return pos;
        } else if (c == ']' || c == '}')
            --depth;
    }
    return std::string::npos;
}

struct RamificationFailure {
    size_t offset;
    std::string message;
};

struct RamificationReader {
    const JsonPositions& positions;

    [[noreturn]] void fail(const std::string& pointer, const std::string& message, bool atKey = false) const {
        const auto& table = atKey ? positions.keys : positions.values;
        const auto found = table.find(pointer);
        throw RamificationFailure{found == table.end() ? 0 : found->second, message};
    }

    double number(const nlohmann::json& value, const std::string& pointer, double min, double max) const {
        if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < min ||
            value.get<double>() > max) {
            std::ostringstream range;
            range << "'" << pointer.substr(1) << "' must be a number in [" << min << ", " << max << "], not "
                  << value.dump();
            fail(pointer, range.str());
        }
        return value.get<double>();
    }

    uint64_t integer(const nlohmann::json& value, const std::string& pointer, uint64_t min, uint64_t max) const {
        if (!value.is_number_unsigned() || value.get<uint64_t>() < min || value.get<uint64_t>() > max) {
            const std::string range = max == std::numeric_limits<uint64_t>::max()
                                          ? " ≥ " + std::to_string(min)
                                          : " in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
            fail(pointer, "'" + pointer.substr(1) + "' must be a whole number" + range + ", not " + value.dump());
        }
        return value.get<uint64_t>();
    }

    RamificationMatrix matrix(const nlohmann::json& p) const {
        if (!p.is_array() || p.empty() || p.size() > kMaxRamificationOrders)
            fail("/p", "'p' must be an array of 1 to " + std::to_string(kMaxRamificationOrders) +
                           " rows, row k holding k numbers");
        RamificationMatrix matrix;
        for (size_t k = 1; k <= p.size(); ++k) {
            const std::string row = "/p/" + std::to_string(k - 1);
            if (!p[k - 1].is_array() || p[k - 1].size() != k)
                fail(row, "row " + std::to_string(k) + " of 'p' must hold " + std::to_string(k) + " numbers (p_" +
                              std::to_string(k) + "1 ... p_" + std::to_string(k) + std::to_string(k) + ")");
            std::vector<double> values;
            for (size_t j = 0; j < k; ++j) {
                const nlohmann::json& entry = p[k - 1][j];
                if (!entry.is_number() || !std::isfinite(entry.get<double>()) || entry.get<double>() < 0.0)
                    fail(row + "/" + std::to_string(j), "p_" + std::to_string(k) + std::to_string(j + 1) +
                                                            " must be a number ≥ 0, not " + entry.dump());
                values.push_back(entry.get<double>());
            }
            matrix.p.push_back(std::move(values));
        }
        return matrix;
    }
};

const std::vector<std::string> kKeys = {
    "p",     "balance",        "depth",       "orders",     "a",          "twist",          "length",
    "width", "width_exponent", "split_angle", "main_angle", "side_angle", "side_angle_min", "phyllotaxis",
    "droop", "stems",          "stem_angle",  "foliage",    "seed",       "max_branches",   "description"};
const std::vector<std::string> kFoliageKeys = {"kind", "orders", "clusters", "per_cluster", "size", "angle", "width"};

void checkKeys(const nlohmann::json& object, const std::string& pointer, const std::vector<std::string>& keys,
               const RamificationReader& reader) {
    for (const auto& [key, value] : object.items())
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            reader.fail(pointer + "/" + key, "unknown key '" + key + "' (docs/RAMIFICATION.md lists the keys)", true);
}

RamificationFoliage readFoliage(const nlohmann::json& object, const RamificationReader& reader) {
    if (!object.is_object()) reader.fail("/foliage", "'foliage' must be an object");
    checkKeys(object, "/foliage", kFoliageKeys, reader);
    RamificationFoliage foliage;
    if (!object.contains("kind") || !object["kind"].is_string() ||
        (object["kind"] != "leaves" && object["kind"] != "needles"))
        reader.fail(object.contains("kind") ? "/foliage/kind" : "/foliage",
                    "'foliage/kind' must be \"leaves\" or \"needles\"");
    foliage.kind = object["kind"] == "leaves" ? RamificationFoliage::Kind::Leaves : RamificationFoliage::Kind::Needles;
    const auto count = [&](const char* key, uint32_t& out, uint32_t max) {
        if (object.contains(key))
            out = static_cast<uint32_t>(reader.integer(object[key], std::string("/foliage/") + key, 1, max));
    };
    const auto number = [&](const char* key, double& out, double min, double max) {
        if (object.contains(key)) out = reader.number(object[key], std::string("/foliage/") + key, min, max);
    };
    count("orders", foliage.maxOrder, kMaxRamificationOrders);
    count("clusters", foliage.clusters, 64);
    count("per_cluster", foliage.perCluster, 64);
    number("size", foliage.size, 1e-6, 1e6);
    number("angle", foliage.angle, 0.0, 180.0);
    number("width", foliage.needleWidth, 0.0, 1e6);
    return foliage;
}

RamificationTree readTree(const nlohmann::json& root, const RamificationReader& reader) {
    if (!root.is_object()) reader.fail("", "a .ram.json file is one JSON object");
    checkKeys(root, "", kKeys, reader);
    if (root.contains("p") == root.contains("balance"))
        reader.fail("", "give either 'p' (the matrix) or 'balance' with 'depth'");
    RamificationTree tree;
    std::optional<uint32_t> depth;
    uint32_t writtenOrders = 0; // rows of 'p', or 'depth' with 'balance': what 'a' counts
    if (root.contains("depth"))
        depth = static_cast<uint32_t>(reader.integer(root["depth"], "/depth", 1, kMaxRamificationOrders));
    if (root.contains("balance")) {
        if (!depth) reader.fail("/balance", "'balance' needs 'depth', the number of orders");
        tree.matrix = balancedMatrix(*depth, reader.number(root["balance"], "/balance", 0.0, 100.0));
        writtenOrders = *depth;
    } else {
        tree.matrix = reader.matrix(root["p"]);
        writtenOrders = tree.matrix.orders();
        if (depth && *depth > tree.matrix.orders())
            reader.fail("/depth", "'depth' must be at most the " + std::to_string(tree.matrix.orders()) +
                                      " rows of 'p' (it removes rows; 'balance' makes any depth)");
        if (depth) tree.matrix.p.resize(*depth);
    }
    if (root.contains("orders") &&
        reader.integer(root["orders"], "/orders", 1, kMaxRamificationOrders) != writtenOrders)
        reader.fail("/orders", "'orders' must be " + std::to_string(writtenOrders) +
                                   ", the rows of 'p' (or 'depth' with 'balance')");
    if (root.contains("a")) {
        const nlohmann::json& a = root["a"];
        if (!a.is_array() || a.size() != writtenOrders)
            reader.fail("/a",
                        "'a' must be an array of the " + std::to_string(writtenOrders) + " branch counts a_1 ... a_K");
        for (size_t k = 0; k < a.size(); ++k)
            reader.integer(a[k], "/a/" + std::to_string(k), 0, std::numeric_limits<uint64_t>::max());
    }
    if (root.contains("description") && !root["description"].is_string())
        reader.fail("/description", "'description' must be a string");
    RamificationGrowth& growth = tree.growth;
    const auto optionalNumber = [&](const char* key, double& out, double min, double max) {
        if (root.contains(key)) out = reader.number(root[key], std::string("/") + key, min, max);
    };
    optionalNumber("twist", growth.twist, 0.0, 360.0);
    optionalNumber("length", growth.length, 1e-6, 1e6);
    optionalNumber("width", growth.width, 0.0, 1e6);
    if (root.contains("width_exponent"))
        growth.widthExponent = reader.number(root["width_exponent"], "/width_exponent", 0.0, 64.0);
    optionalNumber("split_angle", growth.splitAngle, 0.0, 180.0);
    optionalNumber("main_angle", growth.mainAngle, 0.0, 180.0);
    optionalNumber("side_angle", growth.sideAngle, 0.0, 180.0);
    optionalNumber("side_angle_min", growth.minSideAngle, 0.0, 180.0);
    optionalNumber("phyllotaxis", growth.phyllotaxis, 0.0, 360.0);
    optionalNumber("droop", growth.droop, 0.0, 1.0);
    if (root.contains("stems")) growth.stems = static_cast<uint32_t>(reader.integer(root["stems"], "/stems", 1, 64));
    optionalNumber("stem_angle", growth.stemAngle, 0.0, 90.0);
    if (root.contains("foliage")) tree.foliage = readFoliage(root["foliage"], reader);
    if (root.contains("seed"))
        tree.seed = reader.integer(root["seed"], "/seed", 0, std::numeric_limits<uint64_t>::max());
    if (root.contains("max_branches"))
        tree.maxBranches = reader.integer(root["max_branches"], "/max_branches", 1, uint64_t(1) << 40);
    return tree;
}

Diagnostic diagnosticAt(const std::string& file, const std::string& text, size_t offset, std::string message) {
    offset = std::min(offset, text.size());
    const size_t lineStart = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
    Diagnostic diagnostic;
    diagnostic.file = file;
    diagnostic.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
    diagnostic.column = static_cast<int>(offset - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1;
    diagnostic.message = std::move(message);
    return diagnostic;
}

} // namespace

bool isRamificationFile(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    return name.size() > 9 && name.ends_with(".ram.json");
}

RamificationFile parseRamification(std::string text, const std::string& file) {
    RamificationFile result;
    result.source = std::move(text);
    const std::string& source = result.source;
    if (const size_t deep = tooDeepOffset(source); deep != std::string::npos) {
        result.diagnostics.push_back(
            diagnosticAt(file, source, deep, "nests deeper than " + std::to_string(kMaxJsonDepth) + " levels"));
        return result;
    }
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(source);
    } catch (const nlohmann::json::exception& error) {
        // parse_error::byte is the 1-based offset of the last character read;
        // what() says what was wrong there after "column N: ".
        const auto* parse = dynamic_cast<const nlohmann::json::parse_error*>(&error);
        std::string what = error.what();
        if (const size_t detail = what.find(": ", what.find("column ")); detail != std::string::npos)
            what = what.substr(detail + 2);
        const size_t offset = parse && parse->byte > 0 ? parse->byte - 1 : 0;
        result.diagnostics.push_back(diagnosticAt(file, source, offset, "not JSON: " + what));
        return result;
    }
    JsonPositions positions;
    recordValue(source, source.starts_with("\xEF\xBB\xBF") ? 3 : 0, "", positions); // after a UTF-8 BOM
    try {
        result.tree = readTree(root, RamificationReader{positions});
    } catch (const RamificationFailure& failure) {
        result.diagnostics.push_back(diagnosticAt(file, source, failure.offset, failure.message));
    }
    return result;
}

RamificationFile readRamificationFile(const std::filesystem::path& path) {
    std::vector<Diagnostic> diagnostics;
    std::optional<std::string> text = readTextFileOf("ramification", path, kMaxRamificationFileBytes, diagnostics);
    if (!text) {
        RamificationFile result;
        result.diagnostics = std::move(diagnostics);
        return result;
    }
    return parseRamification(std::move(*text), path.string());
}

} // namespace lsys
