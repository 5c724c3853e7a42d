#pragma once
// The turtle's commands, each declared once (lsystem/turtle/turtle_commands.cpp):
// its symbols, parameters, a line of documentation, what it reads and which
// style field it changes, and its state transition. applyModule() runs the
// transition, turtleCommand() resolves names from the symbols, the
// InstanceGraph's status functions (lsystem/instancing/status_function.h) follow the
// reads and changes, and `lsys --help-turtle` prints turtleCommandHelp().
// As in L-Py's predefined modules, which carry their documentation with them.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/language/symbols.h"

namespace lsys {

struct TurtleSettings;
struct TurtleState;
struct TurtleStack;
class PlantAssetBuilder;

// One per command, in the order of its definition in the table; PolygonEnd
// stays last (kTurtleActions). None is every module that is no command.
enum class TurtleAction : uint8_t {
    None,
    Draw,
    Move,
    DrawWithoutVertex,
    MoveWithoutVertex,
    Yaw,
    YawBack,
    Pitch,
    PitchBack,
    Roll,
    RollBack,
    TurnAround,
    RollHorizontal,
    MoveTo,
    SetHeading,
    Push,
    Pop,
    Width,
    Widen,
    Material,
    MaterialDown,
    Cut,
    ScaleLength,
    AddLength,
    SetLength,
    ScaleAngle,
    AddAngle,
    SetAngle,
    ScaleWidth,
    AddWidth,
    AddMaterial,
    Stiffness,
    Elasticity,
    TropismVector,
    MovementElasticityUp,
    MovementElasticityDown,
    Sphere,
    Surface,
    PolygonBegin,
    PolygonVertex,
    PolygonEnd,
};
inline constexpr size_t kTurtleActions = static_cast<size_t>(TurtleAction::PolygonEnd) + 1;

// What a module name means to the turtle, resolved once per symbol.
struct TurtleCommand {
    TurtleAction action = TurtleAction::None;
    std::string surface; // the name after ~ for TurtleAction::Surface
};

// `cpfgModules`: the commands only cpfg's files have (G and g, which native
// grammars use as ordinary modules) are commands too.
TurtleCommand turtleCommand(const std::string& moduleName, bool cpfgModules = false);
// turtleCommand() of every symbol, indexed by SymbolId.
std::vector<TurtleCommand> turtleCommands(const SymbolTable& symbols, bool cpfgModules = false);

// Whether the command draws a segment (a joint) with this many polygons open.
bool drawsSegment(TurtleAction action, size_t openPolygons);

// The style fields of TurtleState: what it holds besides the frame and the joint.
enum class StyleField : uint8_t { Width, Length, Angle, Material, Stiffness, Elasticity, Tropism };
inline constexpr size_t kStyleFields = 7;

// What a command reads of the state it is applied to, as a set of bits: the
// style fields, and two things that are no field of TurtleState. The frame
// and the joint are not listed: an InstanceGraph object's entry frame is its
// instance's transform and its entry joint is remapped, never part of a key.
constexpr uint16_t readBit(StyleField field) { return static_cast<uint16_t>(1u << static_cast<unsigned>(field)); }
inline constexpr uint16_t kReadsNothing = 0;
inline constexpr uint16_t kReadsWidth = readBit(StyleField::Width);
inline constexpr uint16_t kReadsLength = readBit(StyleField::Length);
inline constexpr uint16_t kReadsAngle = readBit(StyleField::Angle);
inline constexpr uint16_t kReadsMaterial = readBit(StyleField::Material);
inline constexpr uint16_t kReadsStiffness = readBit(StyleField::Stiffness);
inline constexpr uint16_t kReadsElasticity = readBit(StyleField::Elasticity);
inline constexpr uint16_t kReadsTropism = readBit(StyleField::Tropism);
inline constexpr uint16_t kReadsWorldUp = 1 << kStyleFields;           // the frame against the world's +Y
inline constexpr uint16_t kReadsPolygonOpen = 1 << (kStyleFields + 1); // whether a vertex is recorded
// The frame itself in plant space, not relative to where the turtle started
// (cpfg's @M and @R): an InstanceGraph whose word holds such a command is one
// object (lsystem/instancing/instance_graph_build.cpp).
inline constexpr uint16_t kReadsPlantFrame = 1 << (kStyleFields + 2);

// Reads that depend on the module and the state: a parameter left out is
// taken from a field, and a zero elasticity skips the tropism bend (ABOP
// §2.4). No default: a definition says what it reads, if only kReadsNothing.
struct TurtleReads {
    constexpr TurtleReads(uint16_t always, uint16_t bare = kReadsNothing, uint16_t bending = kReadsNothing)
        : always(always), bare(bare), bending(bending) {}

    uint16_t always;
    uint16_t bare;    // in addition when the module has no parameters
    uint16_t bending; // in addition when the elasticity is not 0
};

// How a command changes a style field, which is what the provenance of an
// InstanceGraph object's fields follows.
enum class FieldChange : uint8_t {
    Keep,       // not at all
    Set,        // to a parameter: the value no longer depends on the state before
    Derive,     // from its own value (scaled, offset, counted on): depends on what it depended on
    SetInPlant, // to a parameter meant in plant space: seen from a turned frame it depends on the turn
};

// The one style field a command may change: `complete` when the module has
// all the command's parameters, `otherwise` when it has fewer. No default.
struct StyleChange {
    constexpr StyleChange(StyleField field, FieldChange complete, FieldChange otherwise)
        : field(field), complete(complete), otherwise(otherwise) {}

    StyleField field;
    FieldChange complete;
    FieldChange otherwise;
};
// Of a command that only turns, moves, branches or draws (the field is not looked at).
inline constexpr StyleChange kChangesNoStyle{StyleField::Width, FieldChange::Keep, FieldChange::Keep};

// What a transition acts on: one module and the turtle.
struct TurtleStep {
    const TurtleCommand& command;
    std::span<const float> parameters;
    const TurtleSettings& settings;
    TurtleState& state;
    TurtleStack& stack;
    PlantAssetBuilder& out;

    // Parameter i, or fallback when the module has fewer.
    float parameterOr(size_t i, float fallback) const { return i < parameters.size() ? parameters[i] : fallback; }
};
using TurtleTransition = void (*)(const TurtleStep& step);

// What a command does to the branch and polygon stacks, which the summary of
// an InstanceGraph body adds up (the status function's n in the Calgary
// b-grammar thesis, §4.2). No default: a definition says it, if only
// kKeepsStacks.
struct StackEffect {
    constexpr StackEffect(int8_t branches, int8_t polygons, bool cuts = false)
        : branches(branches), polygons(polygons), cuts(cuts) {}

    int8_t branches; // +1 pushes the turtle state, -1 pops it
    int8_t polygons; // +1 opens a polygon, -1 closes one
    bool cuts;       // cuts the rest of the branch
};
inline constexpr StackEffect kKeepsStacks{0, 0};

struct TurtleCommandDefinition {
    TurtleAction action;            // its index in the table
    std::string_view symbol;        // its module name
    std::string_view alias;         // another, if any
    bool symbolIsPrefix = false;    // ~leaf is the command ~ of the surface leaf
    bool cpfgOnly = false;          // a command in cpfg's files only (turtleCommand's cpfgModules)
    bool symbolNotInCpfg = false;   // its symbol (not its alias) is no command in cpfg's files
    std::string_view parameters;    // "name" or "name = what it is when left out", joined by ", "
    std::string_view documentation; // one line
    TurtleReads reads;
    StyleChange changes;
    StackEffect stacks;
    std::optional<TurtleAction> inPolygon; // the command it acts as while a polygon is open
    TurtleTransition apply;
};

// Every command, indexed by TurtleAction.
std::span<const TurtleCommandDefinition, kTurtleActions> turtleCommandDefinitions();
const TurtleCommandDefinition& turtleCommandDefinition(TurtleAction action);
// The definition that acts for action when openPolygons are open (F acts as f inside one).
const TurtleCommandDefinition& actingDefinition(TurtleAction action, size_t openPolygons);
// How many parameters a module of the command may have.
size_t parameterCount(const TurtleCommandDefinition& definition);

// The table of commands, a row per symbol: symbol, parameters and documentation.
std::string turtleCommandHelp();

} // namespace lsys
