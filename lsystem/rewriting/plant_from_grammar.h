#pragma once
// A derived word to the plant it draws: the grammar's interpretation
// (homomorphism) rules, then the turtle with the header's settings — what a
// renderer calls after derive(). Beside the rewriter rather than the turtle
// (lsystem/turtle/turtle.h), which reads a word without rewriting it.

#include "lsystem/common/memory_budget.h"
#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"
#include "lsystem/turtle/plant_asset.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

// Applies the grammar's interpretation (homomorphism) rules, then the turtle
// with the header's settings: what a renderer calls after derive(). Both
// within `memory`.
PlantAsset plantFromGrammar(const Grammar& grammar, const ModuleString& derived,
                            const SurfaceLibrary& surfaces = SurfaceLibrary{},
                            const MemoryBudget& memory = machineMemoryBudget());

} // namespace lsys
