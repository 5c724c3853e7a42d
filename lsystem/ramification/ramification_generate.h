#pragma once
// Trees generated from a ramification matrix (Tankard 2001, §3.3 and §4.2.2):
// a branch of order k ≥ 2 picks column j of row k; j < k gives children of
// orders k (the axis going on) and j, j = k two children of order k − 1; a
// branch of order 1 is a tip. The result is a bracketed word of turtle
// commands (!, F, /, +, -, [, ]) with one F per branch, so the turtle makes
// it a PlantAsset like any L-system's (joints, export, physics), and
// compiling that plant (lsystem/ramification/ramification.h) counts exactly the choices
// made here. Leaves and needles (Tankard 2001, §4.2.2.3: the matrix trees'
// leaves are polygons) hang on the thin branches; compiling skips them, as
// it skips every leaf.

#include <cstdint>
#include <optional>
#include <string>

#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/language/module_string.h"
#include "lsystem/language/symbols.h"
#include "lsystem/ramification/ramification.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// What a branch's order decides besides its children (Tankard 2001, §3.3.3,
// with the functions of §4.2.2.2 after Viennot et al. 1989). Lengths and
// widths in the turtle's units; angles in degrees.
struct RamificationGrowth {
    double length = 0.0625; // c1: a branch of order k is L(k) = c1 k long
    double width = 0.5;     // c2: and W(k) = c2 L(k)^e wide (a diameter)
    // e; none: Tankard's d_t / 2, d_t the tree's depth (its orders).
    std::optional<double> widthExponent;
    // Children of equal order both leave the axis at this angle, on opposite sides.
    double splitAngle = 30.0;
    // Children of orders k and i < k: the order-k one turns c_m i / (k − 1),
    // the order-i one c_s (k − i) / (k − 1), on the other side.
    double mainAngle = 20.0;
    double sideAngle = 50.0;
    // The twist slider t (§3.3.1, §4.2.1.1): each branch point of order k
    // rolls its children's plane about the axis by r t (d_t + 1 − k), r
    // uniform in [0, 1), so branches near the tips twist more.
    double twist = 0.0;
    // Not Tankard's: what makes an excurrent tree (a conifer) rather than a
    // leader with rising limbs. Side branches leave their axis at least this
    // many degrees (θ_s alone turns a lateral of nearly the axis's order only
    // a little); 0 keeps θ_s.
    double minSideAngle = 0.0;
    // Degrees every branch point rolls besides the twist, so successive
    // laterals spiral about the axis (Tankard 2001, §3.2.3.4.1.2.2: 137.5°,
    // the golden angle, spreads them evenly).
    double phyllotaxis = 0.0;
    // The elasticity toward gravity (ABOP §2.4 tropism, the turtle's @Ts) of
    // every side branch and what grows on it: they bend down the more the
    // farther they lean from vertical, under their weight; the trunk and the
    // axes it goes on as stay straight. 0: none.
    double droop = 0.0;
    // Stems from the base, each a whole tree of the matrix's K orders leaning
    // stemAngle degrees out, rolled 360° / stems apart: a shrub's habit.
    uint32_t stems = 1;
    double stemAngle = 0.0;
};

// Leaves or needles on a tree's thin branches. Each branch of order ≤
// maxOrder is drawn as `clusters` pieces with a cluster after each (the last
// at its tip); a cluster is `perCluster` leaves or needles rolled evenly
// about the branch, each cluster rolled by the golden angle from the one
// before. Leaves are the turtle's ~leaf (material 1, leaf); needles flat
// ribbons, segments of material 5 (needle), which the renderer draws as
// blades and compiling skips.
struct RamificationFoliage {
    enum class Kind : uint8_t { None, Leaves, Needles };
    Kind kind = Kind::None;
    uint32_t maxOrder = 1;
    uint32_t clusters = 3;
    uint32_t perCluster = 2;
    double size = 0.1;         // a leaf's or needle's length, turtle units
    double angle = 50.0;       // degrees between it and its branch
    double needleWidth = 0.03; // a needle ribbon's width
};

// A tree type: what a .ram.json file holds (lsystem/ramification/ramification_file.h).
struct RamificationTree {
    RamificationMatrix matrix; // as given; generation guards it (guardedMatrix)
    RamificationGrowth growth;
    RamificationFoliage foliage;
    uint64_t seed = 0;
    uint64_t maxBranches = 1'000'000; // generating more is an error
};

// Generating would pass RamificationTree::maxBranches.
struct RamificationBudgetError : DerivationError {
    using DerivationError::DerivationError;
};

struct GeneratedTree {
    SymbolTable symbols;
    ModuleString word;
    uint64_t branches = 0; // branches drawn (each is one F, or `clusters` with foliage)
};

// The tree of `tree.seed`: the same seed, the same word. Throws
// RamificationBudgetError past tree.maxBranches. A matrix without rows
// gives an empty word.
GeneratedTree generateTree(const RamificationTree& tree);

// The turtle's plant of the word (default turtle settings), within `memory`.
PlantAsset plantOf(const GeneratedTree& tree, const MemoryBudget& memory = machineMemoryBudget());

// An .lsys file that draws the tree: `comment` as // lines, then the word
// as the axiom of a 0-step derivation.
std::string lsystemText(const GeneratedTree& tree, const std::string& comment);

} // namespace lsys
