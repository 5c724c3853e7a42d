#pragma once
// Ramification matrices (Tankard 2001, §2.2, after Viennot et al. 1989):
// the Horton–Strahler order of every branch of a plant, and the statistics of
// which orders each order of branch splits into.
//
// A branch is an edge of the plant's branching tree: a chain of joints
// (lsystem/turtle/plant_asset.h) from the plant's base or a branch point to the next
// branch point or a tip, so a run of segments drawn without branching is one
// branch. A branch point is a joint on which two or more joints grow.
// Orders (§2.2): a terminal branch has order 1; a branch whose two children
// have orders i and j has order max(i, j) when i ≠ j and i + 1 when i = j.
//
// A joint with n > 2 children is read as n − 1 binary branch points in a
// row: the children sorted by decreasing order, the first two joined into a
// zero-length branch, that one joined with the third, and so on; the last
// join is the real branch. The order that gives is the generalised Strahler
// order (the largest child's, plus one when two children share it), and the
// n − 2 zero-length branches are counted in a_k and b_kj like any other, so
// every row of the matrix still sums to 1. Separate roots (segments drawn
// from the plant's base) are separate trees whose counts add up.
//
// docs/RAMIFICATION.md describes the matrix, the .ram.json file and the CLI.

#include <cstdint>
#include <span>
#include <vector>

#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// p[k - 1] is row k: p_k1 … p_kk. Row 1 is [1] (a terminal branch has no
// children; Tankard keeps p_11 "for the sake of completing the form"). For
// k ≥ 2, p_kj (j < k) is the probability that a branch of order k has
// children of orders k and j, and p_kk that its children are both of order
// k − 1.
struct RamificationMatrix {
    std::vector<std::vector<double>> p;

    uint32_t orders() const { return static_cast<uint32_t>(p.size()); }
};

// What compiling a plant counts.
struct RamificationCounts {
    std::vector<uint64_t> a;              // a[k - 1] = a_k: branches of order k
    std::vector<std::vector<uint64_t>> b; // b[k - 1][j - 1] = b_kj (row k has k entries)
};

struct CompiledRamification {
    std::vector<uint32_t> jointOrder; // the order of the branch each joint lies on
    RamificationCounts counts;
};

// The orders and counts of the tree the joints' parents make. Joints of no
// plant (a parent out of range, or a cycle) are treated as roots.
CompiledRamification compileRamification(std::span<const Joint> joints);

// The same for a plant's branches: its joints without its foliage. A segment
// of a two-sided material (needles, grass blades: leaves the renderer draws
// as ribbons) is a leaf, not a branch, as ~leaf surfaces are; a branch
// growing on one hangs from the nearest branch below it. jointOrder holds
// every joint of the plant, 0 for foliage.
CompiledRamification compileRamification(const PlantAsset& plant);

// p_kj = b_kj / a_k, row 1 = [1]; an empty matrix for a plant without joints.
RamificationMatrix ramificationMatrix(const RamificationCounts& counts);

// Tankard 2001, §4.2.1.2 (the balance slider of §3.3.1): row i, column j is
// y = 1 + cos(π (j / i − balance / 100)), each row then divided by its sum.
// `depth` rows; balance in [0, 100].
RamificationMatrix balancedMatrix(uint32_t depth, double balance);

// The smallest p_kk a matrix generates with: a branch of order k continues
// as order k until it splits into two of order k − 1, so with p_kk = 0 the
// axis never ends (Tankard's balance 0 gives exactly that). Its mean length
// is 1 / p_kk branches.
inline constexpr double kMinSplitProbability = 0.02;

// The matrix a tree is generated from: every row divided by its sum; a row
// that sums to 0 becomes a split into two branches of order k − 1 (p_kk = 1);
// p_kk raised to kMinSplitProbability, the row's other entries scaled to
// 1 − p_kk. Row 1 is [1]. Entries must be finite and ≥ 0.
RamificationMatrix guardedMatrix(const RamificationMatrix& matrix);

} // namespace lsys
