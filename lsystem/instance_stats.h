#pragma once
// What `lsys instance` reports about a b-grammar: how many primitives the
// turtle would draw from its word, and how many instances the object-
// instancing hierarchy built from it holds (seed 000 §4.2), without expanding.

#include <cstddef>
#include <cstdint>
#include <string>

#include "lsystem/bgrammar.h"
#include "lsystem/symbols.h"

namespace lsys {

// The turtle modules that become primitives: F (a segment, also a joint),
// ~name (a surface), @O (a sphere) and { (a polygon).
enum class PrimitiveSymbol : uint8_t { None, Segment, Surface, Sphere, Polygon };
PrimitiveSymbol primitiveSymbol(const std::string& name);

struct InstanceStats {
    uint64_t primitives = 0;  // segments + surfaces + spheres + polygons in the word
    uint64_t joints = 0;      // segments
    size_t nodes = 0;         // non-terminals plus the axiom
    // Instances of the hierarchy: references to nodes in all bodies, plus the
    // primitives bodies place directly (each is an instance of a primitive).
    uint64_t instances = 0;
    size_t bytesGraph = 0;    // byteSize() of the b-grammar
    size_t bytesFlat = 0;     // primitives x sizeof(Primitive), the flat PlantAsset's records (saturates)
    double compression() const { return instances == 0 ? 0.0 : static_cast<double>(primitives) / static_cast<double>(instances); }
};

InstanceStats instanceStats(const BGrammar& grammar, const SymbolTable& symbols);

}  // namespace lsys
