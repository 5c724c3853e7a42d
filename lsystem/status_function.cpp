#include "lsystem/status_function.h"

#include <glm/mat3x3.hpp>

namespace lsys {

namespace {

constexpr StyleField kFields[kStyleFields] = {StyleField::Width,    StyleField::Length,    StyleField::Angle,
                                              StyleField::Material, StyleField::Stiffness, StyleField::Elasticity,
                                              StyleField::Tropism};

// The source of a field's entry value: the fields and the first sources share an order.
uint16_t sourceOf(StyleField field) { return static_cast<uint16_t>(1u << static_cast<unsigned>(field)); }

// Copies one style field from a child's state into the parent's; the tropism
// vector is in the child's frame, toParent maps it into the parent's.
void copyField(StyleField field, const TurtleState& from, const glm::mat3& toParent, TurtleState& to) {
    switch (field) {
    case StyleField::Width: to.width = from.width; break;
    case StyleField::Length: to.length = from.length; break;
    case StyleField::Angle: to.angle = from.angle; break;
    case StyleField::Material: to.material = from.material; break;
    case StyleField::Stiffness: to.stiffness = from.stiffness; break;
    case StyleField::Elasticity: to.elasticity = from.elasticity; break;
    case StyleField::Tropism: to.tropism = toParent * from.tropism; break;
    }
}

uint16_t nonPristineSources(const Provenance& provenance) {
    uint16_t reads = 0;
    for (StyleField field : kFields)
        if (!provenance.isPristine(field)) reads |= provenance.sources(field);
    return reads;
}

} // namespace

Provenance Provenance::pristine() {
    Provenance provenance;
    for (StyleField field : kFields) provenance[field] = sourceOf(field) | kPristine;
    return provenance;
}

uint16_t readsOf(const TurtleCommand& command, std::span<const float> p, const TurtleState& state,
                 const Provenance& provenance, size_t openPolygons, size_t localPolygons) {
    auto field = [&](StyleField f) { return provenance.sources(f); };
    // With no polygon of its own open, whether one was open at the entry decides.
    const uint16_t polygon = localPolygons == 0 ? kSourcePolygon : 0;
    const bool bare = p.empty();
    switch (command.action) {
    case TurtleAction::Draw: {
        uint16_t reads = polygon | (bare ? field(StyleField::Length) : 0);
        if (openPolygons > 0) return reads; // moves along a polygon's outline
        reads |= field(StyleField::Width) | field(StyleField::Material) | field(StyleField::Stiffness) |
                 field(StyleField::Elasticity);
        return state.elasticity != 0.0f ? reads | field(StyleField::Tropism) : reads;
    }
    case TurtleAction::Move: return polygon | (bare ? field(StyleField::Length) : 0);
    case TurtleAction::Yaw:
    case TurtleAction::YawBack:
    case TurtleAction::Pitch:
    case TurtleAction::PitchBack:
    case TurtleAction::Roll:
    case TurtleAction::RollBack: return bare ? field(StyleField::Angle) : 0;
    case TurtleAction::RollHorizontal: return kSourceWorldUp;
    case TurtleAction::Sphere: return field(StyleField::Material) | (bare ? field(StyleField::Width) : 0);
    case TurtleAction::Surface:
    case TurtleAction::PolygonBegin: return field(StyleField::Material);
    case TurtleAction::PolygonVertex: return polygon;
    default: return 0; // the rest only write, or derive a field from itself (see updateProvenance)
    }
}

void updateProvenance(const TurtleCommand& command, std::span<const float> p, size_t openPolygons,
                      Provenance& provenance) {
    const bool bare = p.empty();
    // A field set from a parameter depends on nothing; one scaled or offset
    // keeps its sources but is no longer the entry value.
    auto set = [&](StyleField f) { provenance[f] = 0; };
    auto derive = [&](StyleField f) { provenance[f] &= static_cast<uint16_t>(~kPristine); };
    switch (command.action) {
    case TurtleAction::Draw:
        if (openPolygons == 0 && p.size() > 1) set(StyleField::Width);
        break;
    case TurtleAction::Width: bare ? derive(StyleField::Width) : set(StyleField::Width); break;
    case TurtleAction::Material: bare ? derive(StyleField::Material) : set(StyleField::Material); break;
    case TurtleAction::ScaleLength:
    case TurtleAction::AddLength:
        if (!bare) derive(StyleField::Length);
        break;
    case TurtleAction::SetLength:
        if (!bare) set(StyleField::Length);
        break;
    case TurtleAction::ScaleAngle:
    case TurtleAction::AddAngle:
        if (!bare) derive(StyleField::Angle);
        break;
    case TurtleAction::SetAngle:
        if (!bare) set(StyleField::Angle);
        break;
    case TurtleAction::ScaleWidth:
    case TurtleAction::AddWidth:
        if (!bare) derive(StyleField::Width);
        break;
    case TurtleAction::AddMaterial:
        if (!bare) derive(StyleField::Material);
        break;
    case TurtleAction::Stiffness:
        if (!bare) set(StyleField::Stiffness);
        break;
    case TurtleAction::Elasticity:
        if (!bare) set(StyleField::Elasticity);
        break;
    // A world vector: seen from the local frame it depends on the entry orientation.
    case TurtleAction::TropismVector:
        if (p.size() >= 3) provenance[StyleField::Tropism] = kSourceOrientation;
        break;
    default: break;
    }
}

uint16_t exitReads(const StatusFunction& status) {
    uint16_t reads = nonPristineSources(status.exit.provenance);
    for (const LocalState& state : status.pushed) reads |= nonPristineSources(state.provenance);
    return reads;
}

uint16_t parentReads(uint16_t childReads, const Provenance& parent, size_t parentLocalPolygons) {
    uint16_t reads = childReads & (kSourceWorldUp | kSourceOrientation);
    for (StyleField field : kFields)
        if (childReads & sourceOf(field)) reads |= parent.sources(field);
    if ((childReads & kSourcePolygon) && parentLocalPolygons == 0) reads |= kSourcePolygon;
    return reads;
}

std::pair<TurtleState, Provenance> composeState(const TurtleState& parent, const Provenance& parentProvenance,
                                                const LocalState& child, int32_t joint) {
    // Columns: local +X, +Y, +Z of the parent's turtle, i.e. -L, H, U (plant_asset.h's Frame).
    const glm::mat3 toParent(-parent.left, parent.heading, parent.up);
    TurtleState state = parent;
    Provenance provenance = parentProvenance;
    state.position = parent.position + toParent * child.turtle.position;
    state.heading = toParent * child.turtle.heading;
    state.left = toParent * child.turtle.left;
    state.up = toParent * child.turtle.up;
    for (StyleField field : kFields) {
        if (child.provenance.isPristine(field)) continue;
        copyField(field, child.turtle, toParent, state);
        provenance[field] = 0; // the child's key fixes what it depended on
    }
    state.joint = joint;
    return {state, provenance};
}

} // namespace lsys
