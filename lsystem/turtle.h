#pragma once
// The ABOP 3D turtle: reads a module string and produces a PlantAsset
// (primitives, joint skeleton, materials, bounds; lsystem/plant_asset.h).
//
// Frame: heading H, left L, up U, right-handed (H x L = U), kept orthonormal.
// The turtle starts at the origin with H = +Y, L = -X, U = +Z.
//
// The core is a per-module state transition, so that an InstanceGraph can
// interpret a node's body from any entry state and compose the results (seed
// 000 ch. 4, "interpretation status functions"): applyModule() reads one
// module, changes (TurtleState, TurtleStack) and appends primitives to a
// PlantAssetBuilder. What each module reads (R) and writes (W); "out" is the
// builder. Angles are in degrees, widths are diameters (radii = width / 2).
//
//   F(l[,w])  R position H L U width length material stiffness tropism elasticity joint
//             outside a polygon: appends a Segment primitive and a Joint
//             (parent = joint) of length l (default: length) tapering from
//             width to w; W width = w, joint = the new joint, position += H*l,
//             then bends H L U toward the tropism vector (see @Ts).
//             Inside a polygon (TurtleStack::polygons not empty) it draws
//             nothing and acts as f.
//   f(l)      R position H length; W position += H*l. Inside a polygon it also
//             appends the new position to the innermost open polygon.
//   + - (a)   yaw about U by +-a (default: angle); + turns towards L.   W H L
//   & ^ (a)   pitch about L; & pitches down (towards -U).               W H U
//   \ / (a)   roll about H; \ rolls left.                               W L U
//   |         yaw 180 degrees.                                          W H L
//   $         roll about H until L is horizontal (L = Y x H / |Y x H|).  W L U
//   [ ]       push / pop the whole TurtleState on TurtleStack::branches; a ]
//             with nothing pushed is ignored. Open polygons are not popped.
//   !(w) / !  W width = w / width * TurtleSettings::widthFactor.
//   ;(i) / ;  W material = i / material + 1; indices are 0..255 (cpfg's colour
//             map), anything else becomes 0.   ' is the same as ;
//   @Lm @La @Ls (x)  W length *= x, += x, = x        (bare: no change)
//   @Am @Aa @As (x)  W angle  *= x, += x, = x        (bare: no change)
//   @Wm @Wa (x)      W width  *= x, += x             (bare: no change)
//   @Ca(x)           W material += x, kept in 0..255 as for ;  (bare: no change)
//   @K(k)     W stiffness = k for the following segments (Crankshaw's F(l,k)
//             arrives as @K(k)F(l) through the dialect's interpretation rules).
//   @Ts(e)    W elasticity = e. After every drawn segment H turns toward the
//             tropism vector T by e*|H x T| radians about H x T (ABOP §2.4):
//             |T| scales the effect, e < 0 bends away, e = 0 (default) none.
//   @Tv(x,y,z) W tropism = (x,y,z) (default from TurtleSettings: (0,-1,0)).
//   @O(d) / @O  R position H L U width material joint; out: a Sphere of
//             diameter d / of the current width, attached to joint.
//   ~name(s)  R position H L U material joint; out: the predefined surface
//             `name` (SurfaceLibrary) scaled by s (default 1), attached to joint.
//   {         R position H L U material joint; W pushes an open polygon
//             starting at this frame on TurtleStack::polygons.
//   .         R position; W appends position to the innermost open polygon.
//   }         W pops the innermost polygon; out: a PolygonShape and a Polygon
//             primitive (frame, material and joint of its {) when it has 3 or
//             more distinct vertices. Without an open polygon: ignored.
//   %         cuts the rest of the branch: interpretModules() skips to the ]
//             closing it (a string-level operation, not a state transition;
//             the rewriter already removes % produced by rules).
//   @Oc       (an unfilled screen-space circle in cpfg) and every other module
//             change nothing.
//
// Polygons follow cpfg/lpfg: the polygon stack is separate from the branch
// stack, so ABOP Fig 5.6's `[+A{.].C.}` (a polygon opened inside a branch and
// closed after it) works, and F/f record vertices so Robbins' `{+F-F-F}`
// traces a triangle. `{` itself records no vertex; consecutive repeated
// vertices and a last vertex equal to the first are dropped, so ABOP's
// `{.-f.+f.}` records each corner once. A polygon never closed draws nothing.
// A segment of negative length l is drawn backwards: its frame is the
// turtle's turned 180 degrees about U and its length is |l|.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/grammar.h"
#include "lsystem/module_string.h"
#include "lsystem/plant_asset.h"
#include "lsystem/surfaces.h"
#include "lsystem/turtle_builder.h"

namespace lsys {

struct TurtleSettings {
    float angle = 45.0f; // degrees
    float step = 1.0f;
    float width = 1.0f;
    float widthFactor = 0.7f;             // for a bare '!'
    glm::vec3 tropism{0.0f, -1.0f, 0.0f}; // gravity
    float elasticity = 0.0f;
};

// The defaults written in the grammar header (angle:, step:, width:).
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

enum class TurtleAction : uint8_t {
    None,
    Draw,
    Move,
    Yaw,
    YawBack,
    Pitch,
    PitchBack,
    Roll,
    RollBack,
    TurnAround,
    RollHorizontal,
    Push,
    Pop,
    Width,
    Material,
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
    Sphere,
    Surface,
    PolygonBegin,
    PolygonVertex,
    PolygonEnd,
};

// What a module name means to the turtle, resolved once per symbol.
struct TurtleCommand {
    TurtleAction action = TurtleAction::None;
    std::string surface; // the name after ~ for TurtleAction::Surface
};

TurtleCommand turtleCommand(const std::string& moduleName);
// turtleCommand() of every symbol, indexed by SymbolId.
std::vector<TurtleCommand> turtleCommands(const SymbolTable& symbols);

// The per-module state transition documented above. TurtleAction::Cut does
// nothing here (see interpretModules). Throws SurfaceError for a surface the
// builder's library cannot provide.
void applyModule(const TurtleCommand& command, std::span<const float> parameters, const TurtleSettings& settings,
                 TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out);

// applyModule() over a whole string, commands indexed by SymbolId, with % cuts.
void interpretModules(const ModuleString& string, std::span<const TurtleCommand> commands,
                      const TurtleSettings& settings, TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out);

// The plant a derived (and interpreted) string draws from the initial state.
PlantAsset interpretPlant(const ModuleString& string, const SymbolTable& symbols, const TurtleSettings& settings,
                          const SurfaceLibrary& surfaces);

// Applies the grammar's interpretation (homomorphism) rules, then the turtle
// with the header's settings: what a renderer calls after derive().
PlantAsset plantFromGrammar(const Grammar& grammar, const ModuleString& derived,
                            const SurfaceLibrary& surfaces = SurfaceLibrary{});

} // namespace lsys
