// readRamificationFile: a .ram.json file (docs/RAMIFICATION.md) checked value
// by value, each error located by lsystem/common/json_reader.h.
#include "lsystem/ramification/ramification_file.h"

#include "lsystem/common/file_reader.h"
#include "lsystem/common/json_reader.h"

namespace lsys {

namespace {

// A matrix of kMaxRamificationOrders rows is about 40 KiB of JSON.
constexpr size_t kMaxRamificationFileBytes = size_t(1) << 20;
// A .ram.json file nests 3 levels (the object, "p", its rows).
constexpr uint32_t kMaxRamificationDepth = 8;

const JsonDocumentKind kRamificationDocument{"ramification tree", kMaxRamificationFileBytes, kMaxRamificationDepth};

RamificationMatrix readMatrix(const JsonNode& p) {
    const std::string rowsWanted = "1 to " + std::to_string(kMaxRamificationOrders) + " rows, row k holding k numbers";
    const std::vector<JsonNode> rows = arrayElements(p, "an array of " + rowsWanted);
    if (rows.empty() || rows.size() > kMaxRamificationOrders)
        failAt(p, "must hold " + rowsWanted + " (got " + std::to_string(rows.size()) + " rows)");
    RamificationMatrix matrix;
    for (size_t k = 1; k <= rows.size(); ++k) {
        const std::string order = std::to_string(k);
        const std::string entries = order + " numbers (p_" + order + "1 ... p_" + order + order + ")";
        const std::vector<JsonNode> row = arrayElements(rows[k - 1], "an array of " + entries);
        if (row.size() != k) failAt(rows[k - 1], "must hold " + entries + ", not " + std::to_string(row.size()));
        std::vector<double> values;
        for (const JsonNode& entry : row) values.push_back(readNumber(entry, atLeast(0.0)));
        matrix.p.push_back(std::move(values));
    }
    return matrix;
}

RamificationFoliage readFoliage(const JsonNode& node) {
    requireObject(node, {"kind", "orders", "clusters", "per_cluster", "size", "angle", "width"});
    RamificationFoliage foliage;
    const JsonNode kindNode = requireMember(node, "kind", "\"leaves\" or \"needles\"");
    const std::string kind = readString(kindNode);
    if (kind != "leaves" && kind != "needles")
        failAt(kindNode,
               "must be \"leaves\" or \"needles\" (got \"" + kind + "\")" + didYouMean(kind, {"leaves", "needles"}));
    foliage.kind = kind == "leaves" ? RamificationFoliage::Kind::Leaves : RamificationFoliage::Kind::Needles;
    readField(node, "orders", foliage.maxOrder, between(1, kMaxRamificationOrders));
    readField(node, "clusters", foliage.clusters, between(1, 64));
    readField(node, "per_cluster", foliage.perCluster, between(1, 64));
    readField(node, "size", foliage.size, between(1e-6, 1e6));
    readField(node, "angle", foliage.angle, between(0, 180));
    readField(node, "width", foliage.needleWidth, between(0, 1e6));
    return foliage;
}

// The matrix from "p" or from Tankard's sliders "balance" and "depth"
// (§3.3.1), and the orders the file wrote, which "orders" and "a" count.
RamificationMatrix readOrders(const JsonNode& root, uint32_t& writtenOrders) {
    const std::optional<JsonNode> p = member(root, "p");
    const std::optional<JsonNode> balance = member(root, "balance");
    const std::optional<JsonNode> depthNode = member(root, "depth");
    if (p && balance)
        failAt(*balance, "cannot be given together with \"p\": give the matrix or Tankard's balance slider", true);
    std::optional<uint32_t> depth;
    if (depthNode) depth = readInteger(*depthNode, between(1, kMaxRamificationOrders));
    if (balance) {
        if (!depth) failAt(*balance, "needs \"depth\", the number of orders");
        writtenOrders = *depth;
        return balancedMatrix(*depth, readNumber(*balance, between(0, 100)));
    }
    if (!p) failAt(root, "needs \"p\" (the matrix) or \"balance\" with \"depth\"");
    RamificationMatrix matrix = readMatrix(*p);
    writtenOrders = matrix.orders();
    if (depth && *depth > writtenOrders)
        failAt(*depthNode, "must be at most the " + std::to_string(writtenOrders) +
                               " rows of \"p\" (it removes rows; \"balance\" makes any depth)");
    if (depth) matrix.p.resize(*depth);
    return matrix;
}

// "orders" and "a", what `lsys ramify --json` writes besides the matrix:
// checked against it, not used to generate.
void checkCounts(const JsonNode& root, uint32_t writtenOrders) {
    const std::string rows = std::to_string(writtenOrders);
    if (auto orders = member(root, "orders");
        orders && readInteger(*orders, between(1, kMaxRamificationOrders)) != writtenOrders)
        failAt(*orders, "must be " + rows + ", the rows of \"p\" (or \"depth\" with \"balance\")");
    if (auto a = member(root, "a")) {
        const std::vector<JsonNode> counts =
            arrayElements(*a, "an array of the " + rows + " branch counts a_1 ... a_K");
        if (counts.size() != writtenOrders)
            failAt(*a, "must hold the " + rows + " branch counts a_1 ... a_K, not " + std::to_string(counts.size()));
        for (const JsonNode& count : counts) readInteger64(count, anyNumber());
    }
}

RamificationTree readRamificationTree(const JsonNode& root) {
    requireObject(
        root, {"p",     "balance",        "depth",       "orders",     "a",          "twist",          "length",
               "width", "width_exponent", "split_angle", "main_angle", "side_angle", "side_angle_min", "phyllotaxis",
               "droop", "stems",          "stem_angle",  "foliage",    "seed",       "max_branches",   "description"});
    RamificationTree tree;
    uint32_t writtenOrders = 0;
    tree.matrix = readOrders(root, writtenOrders);
    checkCounts(root, writtenOrders);
    if (auto description = member(root, "description")) readString(*description); // for people
    RamificationGrowth& growth = tree.growth;
    readField(root, "twist", growth.twist, between(0, 360));
    readField(root, "length", growth.length, between(1e-6, 1e6));
    readField(root, "width", growth.width, between(0, 1e6));
    if (auto exponent = member(root, "width_exponent")) growth.widthExponent = readNumber(*exponent, between(0, 64));
    readField(root, "split_angle", growth.splitAngle, between(0, 180));
    readField(root, "main_angle", growth.mainAngle, between(0, 180));
    readField(root, "side_angle", growth.sideAngle, between(0, 180));
    readField(root, "side_angle_min", growth.minSideAngle, between(0, 180));
    readField(root, "phyllotaxis", growth.phyllotaxis, between(0, 360));
    readField(root, "droop", growth.droop, between(0, 1));
    readField(root, "stems", growth.stems, between(1, 64));
    readField(root, "stem_angle", growth.stemAngle, between(0, 90));
    if (auto foliage = member(root, "foliage")) tree.foliage = readFoliage(*foliage);
    readField(root, "seed", tree.seed, anyNumber());
    readField(root, "max_branches", tree.maxBranches, between(1, double(kMaxRamificationBranches)));
    return tree;
}

} // namespace

bool isRamificationFile(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    return name.size() > 9 && name.ends_with(".ram.json");
}

RamificationFile parseRamification(std::string text, const std::string& file) {
    RamificationFile result;
    result.source = text; // kept for formatDiagnostics whether or not the text parses
    try {
        const JsonSource source = parseJsonText(std::move(text), file, kRamificationDocument);
        result.tree = readRamificationTree(rootNode(source));
    } catch (const JsonError& error) {
        result.diagnostics.push_back(error.diagnostic);
    }
    return result;
}

RamificationFile readRamificationFile(const std::filesystem::path& path) {
    std::vector<Diagnostic> diagnostics;
    std::optional<std::string> text =
        readTextFileOf(kRamificationDocument.name, path, kMaxRamificationFileBytes, diagnostics);
    if (!text) {
        RamificationFile result;
        result.diagnostics = std::move(diagnostics);
        return result;
    }
    return parseRamification(std::move(*text), path.string());
}

} // namespace lsys
