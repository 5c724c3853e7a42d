#pragma once
// The ABOP 3D turtle: reads a module string and produces the segments a
// renderer draws as cylinders or cones.
//
// Frame: heading H, left L, up U, right-handed (H x L = U), kept orthonormal.
// The turtle starts at the origin with H = +Y, L = -X, U = +Z.
//   F(l[,w])  draw a segment of length l (default: step); with w the segment
//             tapers from the current width to w, which becomes current
//   f(l)      move without drawing
//   + -       yaw about U by +-angle (+ turns towards L)      & ^  pitch about L (& pitches down)
//   \ /       roll about H (\ rolls left)                      |    turn 180 degrees about U
//   $         roll about H until L is horizontal               [ ]  push / pop the whole state
//   !(w)      set width; bare ! multiplies it by kWidthFactor  ;(i) material index; bare ; or ' adds 1
//   %         cut: skip the rest of the current branch
//   @Lm(x) @La(x) @Ls(x)  multiply / add to / set the length of bare F and f
//   @Am(x) @Aa(x) @As(x)  multiply / add to / set the angle of bare turns
//   @Wm(x) @Wa(x)         multiply / add to the width      @Ca(x)  add x to the material index
//             (the dialects' commands, docs/DIALECTS.md); without x they change nothing
// Angles are in degrees; a parameter overrides the current angle or length.
// Width is a diameter: radii are width / 2. Other modules are ignored.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/grammar.h"
#include "lsystem/module_string.h"

namespace lsys {

struct TurtleSegment {
    glm::vec3 start;
    glm::vec3 end;
    float startRadius;
    float endRadius;
    uint32_t material;
    int32_t parent;  // index of the segment it grows on, -1 for a root
};

struct TurtleSettings {
    float angle = 45.0f;  // degrees
    float step = 1.0f;
    float width = 1.0f;
    float widthFactor = 0.7f;  // for a bare '!'
};

// The defaults written in the grammar header (angle:, step:, width:).
TurtleSettings turtleSettings(const Grammar& grammar);

std::vector<TurtleSegment> interpretTurtle(const ModuleString& string, const SymbolTable& symbols,
                                           const TurtleSettings& settings);

// Applies the grammar's interpretation (homomorphism) rules, then the turtle
// with the header's settings: what a renderer calls after derive().
std::vector<TurtleSegment> turtleSegments(const Grammar& grammar, const ModuleString& derived);

}  // namespace lsys
