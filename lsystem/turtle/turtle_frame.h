#pragma once
// How the turtle's commands turn its frame (H, L, U; lsystem/turtle/turtle.h): the
// turns, the roll to horizontal, the tropism bends of ABOP and of cpfg, and
// cpfg's @R. Internal to lsystem/turtle/turtle_commands.cpp, which declares the
// commands that use them.
//
// cpfg's turtle (interpret.c) draws exactly as ABOP's: its turns move H, L
// and U as ours do, but it names -U its up vector (L x H, where ours is
// H x L; it starts at (0, 0, -1)). Where a cpfg file gives or asks for an up
// vector (@R, ?U) it means that one.

#include <span>

#include <glm/vec3.hpp>

namespace lsys {

struct Movement;
struct TurtleState;

// Rotates the two frame vectors other than axis by degrees about axis, then
// re-orthonormalises so rounding does not accumulate.
void rotate(TurtleState& state, glm::vec3 axis, float degrees);

// ABOP's $ (cpfg's @v): L = V x H / |V x H| with V the world up (+Y).
void rollHorizontal(TurtleState& state);

// The bend after a segment toward the state's tropism vector T, by its
// elasticity e (none when e is 0): ABOP's (§2.4), or with `cpfg` cpfg's
// (interpret.c, bend).
void bendTowardTropism(TurtleState& state, bool cpfg);

// cpfg's @R(hx, hy, hz, ux, uy, uz) (blackbox.c, 'R'; fewer than 2
// parameters do nothing, hz is 0 when left out): the heading in plant space,
// and cpfg's up vector when given, nonzero and perpendicular to it;
// otherwise the up vector of the last segment turned with the heading
// (turtle.c, adjust_up_and_left).
void setHeadingAsCpfg(TurtleState& state, std::span<const float> parameters);

// cpfg's movements before a step (movements.c, movement_adjust): the
// tropisms together turn H toward V = sum of e_i (cos γ_i T_i + sin γ_i
// T_i x (H x T_i) / |H x T_i|) by |H x V| radians (at most 1), the up vector
// following as @R's does; then the twists turn the up vector about H toward
// the part of their summed direction perpendicular to H.
void adjustForMovements(TurtleState& state, std::span<const Movement> movements);

// cpfg's @Ti(k, d), @Td(k, d) and @Ts(k, e) (blackbox.c, 'T'): movement k
// (from 1) gets d more or less elasticity (its increment when d is left
// out), or elasticity e (0 when left out). Without k, or with k past the
// movements, nothing changes.
enum class ElasticityChange { Increase, Decrease, Set };
void changeMovementElasticity(TurtleState& state, std::span<const Movement> movements, ElasticityChange change,
                              std::span<const float> parameters);

} // namespace lsys
