#pragma once
// What interpreting a node's body from a local entry frame leaves behind for
// the body that refers to it: the Calgary b-grammar thesis's interpretation status function
// (S, n, g1..gn), plus which entry values it read. Internal to the
// InstanceGraph builder (lsystem/instancing/instance_graph_build.cpp).
//
// The turtle runs on the object's local frame. Each style field carries a
// provenance: the entry values (sources) its current value depends on, and
// whether it still *is* its own entry value (pristine). Reading a field for
// output or control flow adds its sources to the object's key; a pristine
// field at the end passes the caller's value through untouched.

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/instancing/instance_graph.h"
#include "lsystem/turtle/turtle.h"

namespace lsys {

// Entry values an object can read; a set of them is a bit mask.
enum StyleSource : uint16_t {
    kSourceWidth = 1 << 0,
    kSourceLength = 1 << 1,
    kSourceAngle = 1 << 2,
    kSourceMaterial = 1 << 3,
    kSourceStiffness = 1 << 4,
    kSourceElasticity = 1 << 5,
    kSourceTropism = 1 << 6,     // the tropism vector seen from the entry frame
    kSourceWorldUp = 1 << 7,     // the world's +Y seen from the entry frame (`$`)
    kSourceOrientation = 1 << 8, // the whole entry orientation (`@Tv` sets a world vector)
    kSourcePolygon = 1 << 9,     // whether a polygon is open (F then moves and adds vertices)
};
inline constexpr uint16_t kPristine = 1 << 15;

struct Provenance {
    std::array<uint16_t, kStyleFields> fields;

    static Provenance pristine();
    uint16_t& operator[](StyleField field) { return fields[static_cast<size_t>(field)]; }
    uint16_t operator[](StyleField field) const { return fields[static_cast<size_t>(field)]; }
    bool isPristine(StyleField field) const { return ((*this)[field] & kPristine) != 0; }
    uint16_t sources(StyleField field) const { return (*this)[field] & static_cast<uint16_t>(~kPristine); }
};

// A turtle state relative to an object's entry frame, its joint as a JointRef.
struct LocalState {
    TurtleState turtle;
    Provenance provenance;
    JointRef joint = kEntryJoint;
};

// The Calgary b-grammar thesis' status function: S (the state at the end), n and g1..gn (the
// states left pushed, bottom first) and, while a polygon opened outside is
// being traced, the vertices added to it (local positions).
struct StatusFunction {
    LocalState exit;
    std::vector<LocalState> pushed;
    std::vector<glm::vec3> outerVertices;
};

// The entry values a module reads before it is applied to state, from its
// command's TurtleReads: openPolygons counts every open polygon, localPolygons
// those opened inside the object.
uint16_t readsOf(const TurtleCommand& command, std::span<const float> parameters, const TurtleState& state,
                 const Provenance& provenance, size_t openPolygons, size_t localPolygons);

// The provenance after the module is applied, from its command's StyleChange
// (Push and Pop are the caller's).
void updateProvenance(const TurtleCommand& command, std::span<const float> parameters, size_t openPolygons,
                      Provenance& provenance);

// The entry values a status function's results depend on beyond passing them
// through: the caller cannot recompute them, so the object is keyed by them.
uint16_t exitReads(const StatusFunction& status);

// Maps a child object's reads to the parent's: each field source becomes the
// provenance of that field in the parent where the child starts.
uint16_t parentReads(uint16_t childReads, const Provenance& parent, size_t parentLocalPolygons);

// S (or a g) of a child applied to the parent's state where the child starts
// (Fig 4.5's Compose): the frame composed, pristine fields kept from the
// parent, the others set from the child; joint is the parent's handle for the
// child's joint. Returns the state and its provenance in the parent.
std::pair<TurtleState, Provenance> composeState(const TurtleState& parent, const Provenance& parentProvenance,
                                                const LocalState& child, int32_t joint);

} // namespace lsys
