#include "lsystem/rewriting/plant_from_grammar.h"

#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/turtle.h"

namespace lsys {

PlantAsset plantFromGrammar(const Grammar& grammar, const ModuleString& derived, const SurfaceLibrary& surfaces,
                            const MemoryBudget& memory) {
    const TurtleSettings settings = turtleSettings(grammar);
    if (grammar.interpretation.empty()) return interpretPlant(derived, grammar.symbols, settings, surfaces, memory);
    DeriveOptions interpretation;
    interpretation.memory = memory;
    return interpretPlant(applyInterpretation(grammar, derived, interpretation), grammar.symbols, settings, surfaces,
                          memory);
}

} // namespace lsys
