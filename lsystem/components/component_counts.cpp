// countComponentPlant and the budgets it checks: a graph instances its
// components multiplicatively (a tree of trees of leaves), so what it would
// draw is counted from the graph before anything is drawn.
#include "lsystem/components/component_graph.h"

#include <algorithm>

namespace lsys::components {
namespace {

// A component's edges: each component it draws and how many times per draw.
std::vector<std::pair<uint32_t, uint64_t>> drawnBy(const Component& component) {
    uint64_t perChild = 1;
    std::vector<std::pair<uint32_t, uint64_t>> edges;
    if (const Tree* tree = std::get_if<Tree>(&component.kind)) {
        edges.emplace_back(tree->stem, 1);
        perChild = tree->count;
    } else if (const Radial* radial = std::get_if<Radial>(&component.kind)) {
        perChild = radial->count;
    }
    for (uint32_t child : component.children) edges.emplace_back(child, perChild);
    return edges;
}

// Components in an order where every one comes after all that draw it
// (reverse post-order from the root; the reader refused cycles).
std::vector<uint32_t> topologicalOrder(const ComponentGraph& graph) {
    std::vector<uint32_t> postOrder;
    std::vector<bool> seen(graph.components.size(), false);
    auto visit = [&](auto& self, uint32_t index) -> void {
        seen[index] = true;
        for (const auto& [child, times] : drawnBy(graph.components[index]))
            if (!seen[child]) self(self, child);
        postOrder.push_back(index);
    };
    visit(visit, graph.root);
    std::reverse(postOrder.begin(), postOrder.end());
    return postOrder;
}

// Primitives and bytes of one draw of a component.
std::pair<uint64_t, uint64_t> drawSize(const Component& component) {
    if (const Stem* stem = std::get_if<Stem>(&component.kind))
        return {stem->detail, uint64_t(stem->detail) * (sizeof(Primitive) + sizeof(Joint))};
    if (const Leaf* leaf = std::get_if<Leaf>(&component.kind)) {
        const uint64_t points = leaf->polygon.empty() ? 2 * leaf->detail : leaf->polygon.size();
        return {1, sizeof(Primitive) + sizeof(PolygonShape) + points * sizeof(glm::vec3)};
    }
    return {0, 0};
}

// The component drawn (or drawing) most: where a budget error points.
uint32_t largest(const std::vector<uint64_t>& values) {
    return uint32_t(std::max_element(values.begin(), values.end()) - values.begin());
}

} // namespace

ComponentCounts countComponentPlant(const ComponentGraph& graph) {
    ComponentCounts counts;
    counts.draws.assign(graph.components.size(), 0);
    counts.draws[graph.root] = 1;
    for (uint32_t index : topologicalOrder(graph)) {
        const uint64_t draws = counts.draws[index];
        for (const auto& [child, times] : drawnBy(graph.components[index]))
            counts.draws[child] = bytesPlus(counts.draws[child], bytesTimes(draws, times));
        const auto [primitives, bytes] = drawSize(graph.components[index]);
        counts.instances = bytesPlus(counts.instances, draws);
        counts.primitives = bytesPlus(counts.primitives, bytesTimes(draws, primitives));
        counts.bytes = bytesPlus(counts.bytes, bytesTimes(bytesTimes(draws, bytes), 2));
    }
    return counts;
}

void requireWithinBudgets(const ComponentGraph& graph, const ComponentCounts& counts, const MemoryBudget& memory) {
    const auto fail = [&](uint32_t culprit, const std::string& message) {
        const Component& component = graph.components[culprit];
        const uint64_t draws = counts.draws[culprit];
        throw ComponentError(component.location + " is drawn " +
                             (draws == 1 ? std::string("once") : std::to_string(draws) + " times") + ": " + message);
    };
    if (counts.instances > graph.budget.maxInstances)
        fail(largest(counts.draws), "the plant would draw " + std::to_string(counts.instances) +
                                        " components, past the budget of " + std::to_string(graph.budget.maxInstances) +
                                        " (\"budget\": {\"max_instances\"})");
    if (counts.primitives > graph.budget.maxPrimitives) {
        std::vector<uint64_t> primitives(graph.components.size());
        for (size_t i = 0; i < primitives.size(); ++i)
            primitives[i] = bytesTimes(counts.draws[i], drawSize(graph.components[i]).first);
        fail(largest(primitives), "the plant would draw " + std::to_string(counts.primitives) +
                                      " primitives, past the budget of " + std::to_string(graph.budget.maxPrimitives) +
                                      " (\"budget\": {\"max_primitives\"})");
    }
    need(memory, "component plant", counts.bytes);
}

} // namespace lsys::components
