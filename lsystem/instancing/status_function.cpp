#include "lsystem/instancing/status_function.h"

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
    const TurtleReads& declared = actingDefinition(command.action, openPolygons).reads;
    const uint16_t reads = declared.always | (p.empty() ? declared.bare : kReadsNothing) |
                           (state.elasticity != 0.0f ? declared.bending : kReadsNothing);
    uint16_t sources = 0;
    for (StyleField field : kFields)
        if (reads & readBit(field)) sources |= provenance.sources(field);
    if (reads & kReadsWorldUp) sources |= kSourceWorldUp;
    // With no polygon of its own open, whether one was open at the entry decides.
    if ((reads & kReadsPolygonOpen) && localPolygons == 0) sources |= kSourcePolygon;
    return sources;
}

void updateProvenance(const TurtleCommand& command, std::span<const float> p, size_t openPolygons,
                      Provenance& provenance) {
    const TurtleCommandDefinition& definition = actingDefinition(command.action, openPolygons);
    const StyleChange& change = definition.changes;
    switch (p.size() >= parameterCount(definition) ? change.complete : change.otherwise) {
    case FieldChange::Keep: break;
    case FieldChange::Set:
        provenance[change.field] = 0;
        break; // from a parameter: depends on nothing
    // Scaled or offset, it keeps its sources but is no longer the entry value.
    case FieldChange::Derive: provenance[change.field] &= static_cast<uint16_t>(~kPristine); break;
    // Seen from the local frame, a plant-space vector depends on the entry orientation.
    case FieldChange::SetInPlant: provenance[change.field] = kSourceOrientation; break;
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
