#include "lsystem/ramification_generate.h"

#include <cmath>
#include <sstream>

#include "lsystem/random.h"
#include "lsystem/surfaces.h"
#include "lsystem/turtle.h"

namespace lsys {

namespace {

struct TreeSymbols {
    SymbolId draw, width, left, right, roll;
};

// A branch still to be written, or (order 0) the ']' closing a side branch.
struct PendingBranch {
    uint32_t order = 0;
    double turn = 0.0; // degrees, + left, - right; 0 for the trunk
};

// Column j of row k (1-based), drawn as Tankard 2001, §4.2.2.1 walks a row:
// the first column at which the running sum passes the draw.
uint32_t pickColumn(const std::vector<double>& row, RandomStream& random) {
    const double draw = random.uniform();
    double sum = 0.0;
    for (size_t j = 0; j < row.size(); ++j) {
        sum += row[j];
        if (draw < sum) return static_cast<uint32_t>(j + 1);
    }
    return static_cast<uint32_t>(row.size()); // rounding left the sum just under 1
}

struct WordWriter {
    GeneratedTree& tree;
    const TreeSymbols& symbols;

    void module(SymbolId symbol, double parameter) {
        const float value = static_cast<float>(parameter);
        tree.word.push(symbol, std::span<const float>(&value, 1));
    }
    void bare(SymbolId symbol) { tree.word.push(symbol); }
};

} // namespace

GeneratedTree generateTree(const RamificationTree& spec) {
    const RamificationMatrix matrix = guardedMatrix(spec.matrix);
    const RamificationGrowth& growth = spec.growth;
    const uint32_t depth = matrix.orders();
    const double widthExponent = growth.widthExponent.value_or(depth / 2.0);

    GeneratedTree tree;
    const TreeSymbols symbols{tree.symbols.intern("F"), tree.symbols.intern("!"), tree.symbols.intern("+"),
                              tree.symbols.intern("-"), tree.symbols.intern("/")};
    WordWriter out{tree, symbols};
    RandomStream random{splitmix64(spec.seed), 0};
    std::vector<PendingBranch> pending;
    if (depth > 0) pending.push_back({depth, 0.0});
    while (!pending.empty()) {
        const PendingBranch branch = pending.back();
        pending.pop_back();
        if (branch.order == 0) {
            out.bare(kPop);
            continue;
        }
        if (++tree.branches > spec.maxBranches)
            throw RamificationBudgetError("the tree passes its budget of " + std::to_string(spec.maxBranches) +
                                          " branches");
        const uint32_t k = branch.order;
        if (branch.turn > 0.0) out.module(symbols.left, branch.turn);
        if (branch.turn < 0.0) out.module(symbols.right, -branch.turn);
        const double length = growth.length * k;
        out.module(symbols.width, growth.width * std::pow(length, widthExponent));
        out.module(symbols.draw, length);
        if (k == 1) continue;
        // The roll is drawn whatever the twist, so that the twist changes angles, never the branching.
        const double roll = random.uniform() * growth.twist * (depth + 1 - k);
        if (roll != 0.0) out.module(symbols.roll, roll);
        const uint32_t j = pickColumn(matrix.p[k - 1], random);
        PendingBranch main{k - 1, growth.splitAngle}, side{k - 1, growth.splitAngle};
        if (j < k) {
            main = {k, growth.mainAngle * j / (k - 1)};
            side = {j, growth.sideAngle * (k - j) / (k - 1)};
        }
        // Written as F[+side]-main: the side branch first, in brackets, then the axis.
        main.turn = -main.turn;
        pending.push_back(main);
        pending.push_back({0, 0.0});
        pending.push_back(side);
        out.bare(kPush);
    }
    return tree;
}

PlantAsset plantOf(const GeneratedTree& tree, const MemoryBudget& memory) {
    return interpretPlant(tree.word, tree.symbols, TurtleSettings{}, SurfaceLibrary{}, memory);
}

std::string lsystemText(const GeneratedTree& tree, const std::string& comment) {
    std::ostringstream text;
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) text << "// " << line << '\n';
    text << "derivation length: 0\nAxiom: " << toString(tree.word, tree.symbols) << '\n';
    return text.str();
}

} // namespace lsys
