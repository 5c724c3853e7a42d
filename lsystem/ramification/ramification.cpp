#include "lsystem/ramification/ramification.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace lsys {

namespace {

// Grows the counts to hold order k.
void reserveOrder(RamificationCounts& counts, uint32_t k) {
    while (counts.a.size() < k) {
        counts.a.push_back(0);
        counts.b.emplace_back(counts.a.size(), 0);
    }
}

// The order of a branch point's branch from its children's orders, sorted
// decreasing; counts the branch point's split (and, for more than two
// children, the zero-length branches between the binary joins; see the header).
uint32_t joinChildren(std::span<const uint32_t> sortedOrders, RamificationCounts& counts) {
    uint32_t joined = sortedOrders[0];
    for (size_t m = 1; m < sortedOrders.size(); ++m) {
        const uint32_t child = sortedOrders[m]; // ≤ joined: the orders are sorted and joins only grow
        const uint32_t order = child == joined ? joined + 1 : joined;
        reserveOrder(counts, order);
        ++counts.b[order - 1][child == joined ? order - 1 : child - 1];
        if (m + 1 < sortedOrders.size()) ++counts.a[order - 1]; // a zero-length branch between joins
        joined = order;
    }
    return joined;
}

} // namespace

CompiledRamification compileRamification(std::span<const Joint> joints) {
    const size_t n = joints.size();
    // A parent must come before its joint, as the turtle and flatten() write
    // them; anything else is a root, which also rules out cycles.
    const auto parentOf = [&](size_t i) -> int64_t {
        const int32_t parent = joints[i].parent;
        return parent >= 0 && static_cast<size_t>(parent) < i ? parent : -1;
    };
    std::vector<uint32_t> childCount(n, 0);
    for (size_t i = 0; i < n; ++i)
        if (const int64_t parent = parentOf(i); parent >= 0) ++childCount[parent];
    std::vector<size_t> firstChild(n + 1, 0);
    for (size_t i = 0; i < n; ++i) firstChild[i + 1] = firstChild[i] + childCount[i];
    std::vector<uint32_t> children(firstChild[n]);
    std::vector<size_t> filled(firstChild.begin(), firstChild.end() - 1);
    for (size_t i = 0; i < n; ++i)
        if (const int64_t parent = parentOf(i); parent >= 0) children[filled[parent]++] = static_cast<uint32_t>(i);

    CompiledRamification result;
    result.jointOrder.assign(n, 1);
    std::vector<uint32_t> orders;
    // Children come after their parent, so walking backwards meets every
    // child's order before its parent needs it.
    for (size_t i = n; i-- > 0;) {
        const std::span<const uint32_t> kids(children.data() + firstChild[i], childCount[i]);
        if (kids.empty()) continue; // a tip: order 1
        if (kids.size() == 1) {
            result.jointOrder[i] = result.jointOrder[kids[0]]; // the same branch goes on
            continue;
        }
        orders.clear();
        for (uint32_t child : kids) orders.push_back(result.jointOrder[child]);
        std::sort(orders.begin(), orders.end(), std::greater<>());
        result.jointOrder[i] = joinChildren(orders, result.counts);
    }
    // A branch starts at a root or at a child of a branch point.
    for (size_t i = 0; i < n; ++i) {
        const int64_t parent = parentOf(i);
        if (parent >= 0 && childCount[parent] == 1) continue;
        reserveOrder(result.counts, result.jointOrder[i]);
        ++result.counts.a[result.jointOrder[i] - 1];
    }
    return result;
}

CompiledRamification compileRamification(const PlantAsset& plant) {
    std::vector<bool> foliage(plant.joints.size(), false);
    for (const Primitive& primitive : plant.primitives)
        if (primitive.kind == PrimitiveKind::Segment && primitive.joint >= 0 &&
            static_cast<size_t>(primitive.joint) < foliage.size() && primitive.material < plant.materials.size())
            foliage[primitive.joint] = plant.materials[primitive.material].twoSided;
    // woodyIndex[i]: joint i's index among the branches, or (foliage) that of the branch it hangs on.
    std::vector<int32_t> woodyIndex(plant.joints.size(), -1);
    std::vector<Joint> woody;
    for (size_t i = 0; i < plant.joints.size(); ++i) {
        const int32_t parent = plant.joints[i].parent;
        const int32_t below = parent >= 0 && static_cast<size_t>(parent) < i ? woodyIndex[parent] : -1;
        if (foliage[i]) {
            woodyIndex[i] = below;
            continue;
        }
        woodyIndex[i] = static_cast<int32_t>(woody.size());
        woody.push_back(plant.joints[i]);
        woody.back().parent = below;
    }
    CompiledRamification woodyCompiled = compileRamification(woody);
    CompiledRamification result{std::vector<uint32_t>(plant.joints.size(), 0), std::move(woodyCompiled.counts)};
    for (size_t i = 0; i < plant.joints.size(); ++i)
        if (!foliage[i]) result.jointOrder[i] = woodyCompiled.jointOrder[woodyIndex[i]];
    return result;
}

RamificationMatrix ramificationMatrix(const RamificationCounts& counts) {
    RamificationMatrix matrix;
    for (size_t k = 1; k <= counts.a.size(); ++k) {
        std::vector<double> row(k, 0.0);
        if (k == 1)
            row[0] = 1.0;
        else if (counts.a[k - 1] > 0)
            for (size_t j = 0; j < k; ++j) row[j] = double(counts.b[k - 1][j]) / double(counts.a[k - 1]);
        matrix.p.push_back(std::move(row));
    }
    return matrix;
}

RamificationMatrix balancedMatrix(uint32_t depth, double balance) {
    RamificationMatrix matrix;
    for (uint32_t i = 1; i <= depth; ++i) {
        std::vector<double> row(i);
        double sum = 0.0;
        for (uint32_t j = 1; j <= i; ++j) {
            row[j - 1] = 1.0 + std::cos(std::numbers::pi * (double(j) / double(i) - balance / 100.0));
            sum += row[j - 1];
        }
        // Row 1's only y is 0 at balance 0; it is [1] whatever the balance.
        for (double& value : row) value = i == 1 ? 1.0 : value / sum;
        matrix.p.push_back(std::move(row));
    }
    return matrix;
}

RamificationMatrix guardedMatrix(const RamificationMatrix& matrix) {
    RamificationMatrix guarded = matrix;
    for (size_t k = 1; k <= guarded.p.size(); ++k) {
        std::vector<double>& row = guarded.p[k - 1];
        row.resize(k, 0.0);
        double sum = 0.0;
        for (double value : row) sum += value;
        if (k == 1 || sum <= 0.0) {
            std::fill(row.begin(), row.end(), 0.0);
            row.back() = 1.0;
            continue;
        }
        for (double& value : row) value /= sum;
        if (row.back() < kMinSplitProbability) {
            const double scale = (1.0 - kMinSplitProbability) / (1.0 - row.back());
            for (double& value : row) value *= scale;
            row.back() = kMinSplitProbability;
        }
    }
    return guarded;
}

} // namespace lsys
