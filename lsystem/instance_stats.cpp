#include "lsystem/instance_stats.h"

#include <cstdint>

#include "lsystem/plant_asset.h"

namespace lsys {

PrimitiveSymbol primitiveSymbol(const std::string& name) {
    if (name == "F") return PrimitiveSymbol::Segment;
    if (name.size() > 1 && name[0] == '~') return PrimitiveSymbol::Surface;
    if (name == "@O") return PrimitiveSymbol::Sphere;
    if (name == "{") return PrimitiveSymbol::Polygon;
    return PrimitiveSymbol::None;
}

InstanceStats instanceStats(const BGrammar& grammar, const SymbolTable& symbols) {
    std::vector<PrimitiveSymbol> kinds(symbols.size());
    for (size_t id = 0; id < symbols.size(); ++id) kinds[id] = primitiveSymbol(symbols.name(static_cast<SymbolId>(id)));

    InstanceStats stats;
    const std::vector<uint64_t> counts = countModules(grammar);
    for (size_t id = 0; id < counts.size(); ++id) {
        if (kinds[id] == PrimitiveSymbol::None) continue;
        stats.primitives += counts[id];
        if (kinds[id] == PrimitiveSymbol::Segment) stats.joints += counts[id];
    }
    stats.nodes = grammar.nodes.size();
    stats.instances = nodeReferences(grammar);
    for (const BodyItem& item : grammar.body)
        if (!item.isNode() && kinds[grammar.modules[item.index].symbol] != PrimitiveSymbol::None) ++stats.instances;
    stats.bytesGraph = byteSize(grammar);
    if (__builtin_mul_overflow(stats.primitives, sizeof(Primitive), &stats.bytesFlat)) stats.bytesFlat = SIZE_MAX;
    return stats;
}

}  // namespace lsys
