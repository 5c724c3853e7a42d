#include "lsystem/ramification/ramification_generate.h"

#include <cmath>
#include <sstream>

#include "lsystem/common/random.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"

namespace lsys {

namespace {

struct TreeSymbols {
    SymbolId draw, width, left, right, roll, pitch, material, surface, elasticity;

    explicit TreeSymbols(SymbolTable& table)
        : draw(table.intern("F")), width(table.intern("!")), left(table.intern("+")), right(table.intern("-")),
          roll(table.intern("/")), pitch(table.intern("&")), material(table.intern(";")),
          surface(table.intern("~leaf")), elasticity(table.intern("@Ts")) {}
};

// The turtle's default palette (lsystem/turtle/turtle_builder.h): what foliage is drawn in.
constexpr double kLeafMaterial = 1.0;
constexpr double kNeedleMaterial = 5.0;
// Degrees between successive foliage clusters: the golden angle spreads them evenly.
constexpr double kGoldenAngle = 137.50776405003785;

// A branch still to be written, or (order 0) the ']' closing a side branch.
struct PendingBranch {
    uint32_t order = 0;
    double turn = 0.0; // degrees, + left, - right; 0 for the trunk
    bool side = false; // written in brackets: droop starts here, the axis it leaves stays as it grew
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

// Writes one tree type's word, branch by branch, with one random stream.
struct TreeWriter {
    const RamificationTree& spec;
    const RamificationMatrix matrix;
    const uint32_t depth;
    const double widthExponent;
    GeneratedTree& tree;
    const TreeSymbols symbols;
    RandomStream random;

    TreeWriter(const RamificationTree& spec, GeneratedTree& tree)
        : spec(spec), matrix(guardedMatrix(spec.matrix)), depth(matrix.orders()),
          widthExponent(spec.growth.widthExponent.value_or(depth / 2.0)), tree(tree),
          symbols(tree.symbols), random{splitmix64(spec.seed), 0} {}

    void module(SymbolId symbol, double parameter) {
        const float value = static_cast<float>(parameter);
        tree.word.push(symbol, std::span<const float>(&value, 1));
    }
    void bare(SymbolId symbol) { tree.word.push(symbol); }

    // A leaf or needle cluster after piece `cluster` of a branch.
    void cluster(uint32_t cluster) {
        const RamificationFoliage& foliage = spec.foliage;
        for (uint32_t m = 0; m < foliage.perCluster; ++m) {
            bare(kPush);
            module(symbols.roll, std::fmod(kGoldenAngle * cluster + 360.0 * m / foliage.perCluster, 360.0));
            module(symbols.pitch, foliage.angle);
            if (foliage.kind == RamificationFoliage::Kind::Leaves) {
                module(symbols.material, kLeafMaterial);
                module(symbols.surface, foliage.size);
            } else {
                module(symbols.material, kNeedleMaterial);
                module(symbols.width, foliage.needleWidth);
                module(symbols.draw, foliage.size);
            }
            bare(kPop);
        }
    }

    // The branch's own segment: one F, or with foliage `clusters` pieces each followed by a cluster.
    void branchSegment(uint32_t k, double length) {
        module(symbols.width, spec.growth.width * std::pow(length, widthExponent));
        const RamificationFoliage& foliage = spec.foliage;
        if (foliage.kind == RamificationFoliage::Kind::None || k > foliage.maxOrder) {
            module(symbols.draw, length);
            return;
        }
        for (uint32_t c = 0; c < foliage.clusters; ++c) {
            module(symbols.draw, length / foliage.clusters);
            cluster(c);
        }
    }

    // An order-`trunk` tree from the turtle's place, written depth first.
    void axis(uint32_t trunk) {
        const RamificationGrowth& growth = spec.growth;
        std::vector<PendingBranch> pending{{trunk, 0.0}};
        while (!pending.empty()) {
            const PendingBranch branch = pending.back();
            pending.pop_back();
            if (branch.order == 0) {
                bare(kPop);
                continue;
            }
            if (++tree.branches > spec.maxBranches)
                throw RamificationBudgetError("the tree passes its budget of " + std::to_string(spec.maxBranches) +
                                              " branches");
            const uint32_t k = branch.order;
            if (branch.turn > 0.0) module(symbols.left, branch.turn);
            if (branch.turn < 0.0) module(symbols.right, -branch.turn);
            if (branch.side && growth.droop > 0.0) module(symbols.elasticity, growth.droop);
            branchSegment(k, growth.length * k);
            if (k == 1) continue;
            // The roll is drawn whatever the twist, so that the twist changes angles, never the branching.
            const double roll = growth.phyllotaxis + random.uniform() * growth.twist * (depth + 1 - k);
            if (roll != 0.0) module(symbols.roll, roll);
            const uint32_t j = pickColumn(matrix.p[k - 1], random);
            PendingBranch main{k - 1, growth.splitAngle}, side{k - 1, growth.splitAngle, true};
            if (j < k) {
                main = {k, growth.mainAngle * j / (k - 1)};
                side = {j, std::max(growth.sideAngle * (k - j) / (k - 1), growth.minSideAngle), true};
            }
            // Written as F[+side]-main: the side branch first, in brackets, then the axis.
            main.turn = -main.turn;
            pending.push_back(main);
            pending.push_back({0, 0.0});
            pending.push_back(side);
            bare(kPush);
        }
    }
};

} // namespace

GeneratedTree generateTree(const RamificationTree& spec) {
    GeneratedTree tree;
    TreeWriter writer(spec, tree);
    if (writer.depth == 0) return tree;
    const RamificationGrowth& growth = spec.growth;
    if (growth.stems <= 1) {
        writer.axis(writer.depth);
        return tree;
    }
    for (uint32_t stem = 0; stem < growth.stems; ++stem) {
        writer.bare(kPush);
        writer.module(writer.symbols.roll, 360.0 * stem / growth.stems);
        writer.module(writer.symbols.pitch, growth.stemAngle);
        writer.axis(writer.depth);
        writer.bare(kPop);
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
