#pragma once
// The ABOP 3D turtle: reads a module string and produces a PlantAsset
// (primitives, joint skeleton, materials, bounds; lsystem/turtle/plant_asset.h).
//
// Frame: heading H, left L, up U, right-handed (H x L = U), kept orthonormal.
// The turtle starts at the origin with H = +Y, L = -X, U = +Z. (cpfg's turtle
// turns the same way but calls -U its up vector: lsystem/turtle/turtle_frame.h.)
//
// The core is a per-module state transition, so that an InstanceGraph can
// interpret a node's body from any entry state and compose the results (its
// interpretation status functions, lsystem/instancing/status_function.h): applyModule()
// reads one module, changes (TurtleState, TurtleStack) and appends primitives
// to a PlantAssetBuilder. Each command is defined once, with what it reads and
// changes, in lsystem/turtle/turtle_commands.cpp; `lsys --help-turtle` lists them.
// Angles are in degrees, widths are diameters (radii = width / 2).
//
// Polygons follow cpfg/lpfg: the polygon stack is separate from the branch
// stack, so ABOP Fig 5.6's `[+A{.].C.}` (a polygon opened inside a branch and
// closed after it) works, and F/f record vertices so Robbins' `{+F-F-F}`
// traces a triangle. `{` itself records no vertex; consecutive repeated
// vertices and a last vertex equal to the first are dropped, so ABOP's
// `{.-f.+f.}` records each corner once. A polygon never closed draws nothing.
// A segment of negative length l is drawn backwards: its frame is the
// turtle's turned 180 degrees about U and its length is |l|.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/common/memory_budget.h"
#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"
#include "lsystem/turtle/plant_asset.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle_builder.h"
#include "lsystem/turtle/turtle_commands.h"

namespace lsys {

struct TurtleSettings {
    float angle = 45.0f; // degrees
    float step = 1.0f;
    float width = 1.0f;
    float widthFactor = 0.7f;    // a bare ! multiplies by it, a bare # divides by it,
    float widthIncrement = 0.0f; // then ! subtracts this and # adds it
    int colorIncrement = 1;      // of a bare ; (up) and , (down)
    uint32_t material = 0;
    glm::vec3 tropism{0.0f, -1.0f, 0.0f}; // gravity
    float elasticity = 0.0f;
    bool pixelLines = false;  // widths are screen pixels (widenPixelLines)
    bool cpfgModules = false; // cpfg's turtle: G, g, @M and @R are commands (turtleCommands), cpfg's tropism bend
    std::vector<Movement> movements;
    PlantLook look;
};

// The defaults written in the grammar header (angle:, step:, width:) and its style.
TurtleSettings turtleSettings(const Grammar& grammar);

struct TurtleState {
    glm::vec3 position{0.0f};
    glm::vec3 heading{0.0f, 1.0f, 0.0f};
    glm::vec3 left{-1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float width = 1.0f;
    float length = 1.0f; // of a bare F or f
    float angle = 45.0f; // of a bare turn, degrees
    uint32_t material = 0;
    float stiffness = 0.0f; // of the following segments' joints
    glm::vec3 tropism{0.0f, -1.0f, 0.0f};
    float elasticity = 0.0f;
    int32_t joint = -1; // the last segment drawn on the current path; -1: the plant's base
    // H and U where the last segment (F, G) ended, or the start's: what
    // cpfg's @R turns the up vector from (prev_heading and prev_up, cpfg
    // turtle.c, adjust_up_and_left). The InstanceGraph does not carry them
    // across instances: only @R reads them, and a word holding @R is one object.
    glm::vec3 segmentHeading{0.0f, 1.0f, 0.0f};
    glm::vec3 segmentUp{0.0f, 0.0f, 1.0f};
    // The current elasticity of each of the settings' movements (Movement).
    std::array<float, kMaxMovements> movementElasticity{};
};

// The start of a plant: the settings' width, step, angle, tropism and elasticity.
TurtleState initialTurtleState(const TurtleSettings& settings);

// The turtle's position and orientation as a plant_asset.h Frame.
Frame frameOf(const TurtleState& state);

struct OpenPolygon {
    Frame start; // where { was read
    uint32_t material = 0;
    int32_t joint = -1;
    std::vector<glm::vec3> outline; // plant space
};

struct TurtleStack {
    std::vector<TurtleState> branches; // [ pushes, ] pops
    std::vector<OpenPolygon> polygons; // { pushes, } pops; independent of the branches
};

// The command's transition (turtle_commands.cpp); inside a polygon the one
// it acts as there. TurtleAction::Cut does nothing here (see
// interpretModules). Throws SurfaceError for a surface the builder's library
// cannot provide.
void applyModule(const TurtleCommand& command, std::span<const float> parameters, const TurtleSettings& settings,
                 TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out);

// applyModule() over a whole string, commands indexed by SymbolId, with % cuts.
void interpretModules(const ModuleString& string, std::span<const TurtleCommand> commands,
                      const TurtleSettings& settings, TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out);

// At most what interpreting the string appends to a PlantAsset and to the
// turtle's stacks, from the commands its modules are (a segment's primitive
// and joint, a vertex, a pushed state), twice for the vectors' growth.
uint64_t turtleBytes(const ModuleString& string, std::span<const TurtleCommand> commands);

// The plant a derived (and interpreted) string draws from the initial state.
// Throws MemoryBudgetError (stage "turtle") when turtleBytes() is past `memory`.
PlantAsset interpretPlant(const ModuleString& string, const SymbolTable& symbols, const TurtleSettings& settings,
                          const SurfaceLibrary& surfaces, const MemoryBudget& memory = machineMemoryBudget());

// cpfg draws lines `pixels` wide on a window that its plant fills
// (InitializeParameters' auto window): a pixel is this fraction of the
// plant's larger extent across the view, the default window's 320 x 240
// pixels seen at the larger side.
inline constexpr float kPixelsAcrossPlant = 320.0f;

// The length of a pixel for a plant of these bounds: its larger extent in
// x and y over kPixelsAcrossPlant.
float worldPerPixel(const Bounds& bounds);

// Multiplies every segment's and joint's radii by `factor`; returns the widest segment radius after.
float scaleLineRadii(PlantAsset& plant, float factor);

// Makes a plant interpreted with pixel widths (TurtleSettings::pixelLines)
// what cpfg shows: every segment's and joint's radii times worldPerPixel,
// and bounds grown by the widest new radius.
void widenPixelLines(PlantAsset& plant);

} // namespace lsys
