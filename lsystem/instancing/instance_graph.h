#pragma once
// The object-instancing hierarchy of the Calgary b-grammar thesis (§4.2) built
// from a b-grammar (lsystem/instancing/bgrammar.h): each node becomes an object, each
// reference to a node in a body an instance of it, placed by the turtle state
// accumulated over the body before it. docs/INSTANCING.md describes the model;
// in short:
//
// - An object is the turtle's interpretation of a node's word from a local
//   entry frame (the identity): its primitives are in that local space, and
//   the rigid part of the entry state is always the instance's transform.
// - The rest of the turtle state (width, length, angle, material, stiffness,
//   elasticity, tropism, the world's vertical for `$`, an open polygon) can
//   change what a node draws, so an object is keyed by (node, the entry values
//   its interpretation actually read). Nodes that read none of them are shared
//   exactly, whatever state they are entered with.
// - Orientation-dependent commands (tropism bends, `$`, `@Tv`) read the entry
//   orientation only through world vectors seen from the local frame; keying
//   on those shares subtrees whose entry orientations differ by a rotation
//   about the vector (the thesis' Theorem 5.1), within a granularity pi/G.
// - Commands that place the turtle in plant space (cpfg's @M and @R) make
//   the graph one object: the root interprets the whole word.
// - Joints: an object's primitives refer to the joints of its own subtree, in
//   drawing order, or to the joint current when the instance starts.
// - Every object carries its local bounds, so a renderer can cull a subtree.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/language/grammar.h"
#include "lsystem/turtle/plant_asset.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

// A joint as an object sees it: kEntryJoint, the joint current when the
// instance starts (-1, the plant's base, at the root), or the index of a joint
// among the joints its subtree draws, in drawing order. 64 bits: a subtree of
// a deep bush draws more than 2^31 segments.
using JointRef = int64_t;
inline constexpr JointRef kEntryJoint = -1;

// A primitive an object draws itself, in the object's local space.
struct GraphPrimitive {
    Frame frame;
    PrimitiveKind kind = PrimitiveKind::Segment;
    uint32_t material = 0;
    // Surface: index into InstanceGraph::surfaceNames; Polygon: into InstanceGraph::polygons.
    uint32_t shape = 0;
    float length = 0.0f;
    float startRadius = 0.0f;
    float endRadius = 0.0f;
    float stiffness = 0.0f;             // Segment: of its joint
    JointRef joint = kEntryJoint;       // a Segment's own joint; what other primitives move with
    JointRef parentJoint = kEntryJoint; // Segment: the joint it grows on
};

// An instance of an object inside another: its frame in the parent's space
// and the parent's joint current where it starts.
struct GraphInstance {
    uint32_t object = 0;
    Frame frame;
    JointRef entryJoint = kEntryJoint;
};

// One entry of an object, in drawing order.
struct GraphItem {
    enum class Kind : uint8_t { Primitive, Instance };
    Kind kind = Kind::Primitive;
    uint32_t index = 0; // into InstanceGraph::primitives or InstanceGraph::instances
};

struct GraphObject {
    uint32_t node = 0; // the b-grammar node it interprets
    uint32_t itemStart = 0;
    uint32_t itemCount = 0;
    Bounds bounds;           // of everything the subtree draws, in local space
    uint64_t primitives = 0; // the subtree's, flattened
    uint64_t joints = 0;     // the subtree's (its segments)
};

struct InstanceGraph {
    std::vector<GraphObject> objects; // children before parents
    std::vector<GraphItem> items;     // the objects' items, back to back
    std::vector<GraphPrimitive> primitives;
    std::vector<GraphInstance> instances;
    std::vector<PolygonShape> polygons;    // outlines in the space of the object drawing them
    std::vector<std::string> surfaceNames; // of GraphPrimitive::shape for surfaces
    size_t nodes = 0;                      // of the b-grammar
    uint32_t root = 0;                     // the axiom's object, interpreted from the plant's start
    PlantLook look;                        // the grammar's TurtleStyle::look, which flattening and export apply
    // The grammar's TurtleStyle::pixelLines: flattening widens the plant as
    // the turtle's does; export scales each object's lines by the root's bounds.
    bool pixelLines = false;

    std::span<const GraphItem> itemsOf(uint32_t object) const {
        return {items.data() + objects[object].itemStart, objects[object].itemCount};
    }
};

// The frame of a local frame placed in a parent frame, and a local box placed
// the same way (the box of its corners).
Frame compose(const Frame& parent, const Frame& local);
Bounds transformed(const Bounds& local, const Frame& frame);

struct InstanceGraphOptions {
    // G of the Calgary b-grammar thesis, §5.3: entries whose tropism vector (and
    // world vertical, for `$`) seen from the entry frame fall in the same cell of
    // pi/G in both spherical angles share an object. 0: only identical ones (exact).
    int orientationGranularity = 0;
    size_t maxObjects = 1'000'000; // DerivationError past it
    // The graph's arrays and the builder's per-object records, checked before
    // every object and every run of primitives is added (stage "instance graph").
    MemoryBudget memory = machineMemoryBudget();
};

// The hierarchy of the b-grammar's word, which must be the word the turtle
// reads (BGrammarOptions::interpreted, when the grammar has interpretation
// rules). The turtle settings come from the grammar's header; surfaces bound
// their primitives. Throws DerivationError past options.maxObjects,
// SurfaceError for a surface the library lacks, std::invalid_argument for a
// b-grammar that is not the interpreted word.
InstanceGraph buildInstanceGraph(const BGrammar& bgrammar, const Grammar& grammar,
                                 const InstanceGraphOptions& options = {},
                                 const SurfaceLibrary& surfaces = SurfaceLibrary{});

// The plant the hierarchy stands for, walked from the root with accumulated
// transforms: the PlantAsset interpreting the whole word gives. Throws
// DerivationError when it would hold more than maxPrimitives primitives.
PlantAsset flatten(const InstanceGraph& graph, const SurfaceLibrary& surfaces = SurfaceLibrary{},
                   uint64_t maxPrimitives = 50'000'000);

// The material table flatten(graph) gives its plant (PlantAsset::materials),
// without flattening: every object is drawn somewhere, so the indices its
// primitives use and the surfaces and polygons among them are the plant's.
std::vector<Material> materialsOf(const InstanceGraph& graph);

struct InstanceGraphStats {
    size_t nodes = 0;        // of the b-grammar
    size_t objects = 0;      // distinct (node, entry values read)
    uint64_t instances = 0;  // child references plus primitives placed directly, over all objects
    uint64_t primitives = 0; // after flattening, from memoised counts
    uint64_t joints = 0;
    size_t bytesGraph = 0; // the graph's arrays
    size_t bytesFlat = 0;  // primitives x sizeof(Primitive) (saturates)
    double compression() const {
        return instances == 0 ? 0.0 : static_cast<double>(primitives) / static_cast<double>(instances);
    }
};

InstanceGraphStats instanceGraphStats(const InstanceGraph& graph);

// A statistic by the name `lsys instance --json` and Python's
// instance_stats give it: the one list both print, in that order.
struct NamedInstanceStat {
    std::string_view name;
    std::variant<uint64_t, double> value;
};
std::vector<NamedInstanceStat> namedStats(const InstanceGraphStats& stats);

} // namespace lsys
