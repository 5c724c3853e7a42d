#include "lsystem/queries.h"

#include <array>

#include "lsystem/surfaces.h"
#include "lsystem/turtle.h"
#include "lsystem/turtle_builder.h"

namespace lsys {

namespace {

// The query each symbol answers after a '?': 0 none, else 1 + the index of
// the vector in kQueryNames (position, heading, left, up).
constexpr std::array<const char*, 4> kQueryNames = {"P", "H", "L", "U"};

std::vector<uint8_t> queryKinds(const SymbolTable& symbols) {
    std::vector<uint8_t> kinds(symbols.size(), 0);
    for (size_t k = 0; k < kQueryNames.size(); ++k)
        if (std::optional<SymbolId> id = symbols.find(kQueryNames[k])) kinds[*id] = static_cast<uint8_t>(k + 1);
    return kinds;
}

bool holdsQuery(const std::vector<SuccessorModule>& modules, SymbolId question, const std::vector<uint8_t>& kinds) {
    for (size_t i = 0; i + 1 < modules.size(); ++i)
        if (modules[i].symbol == question && kinds[modules[i + 1].symbol]) return true;
    return false;
}

glm::vec3 answer(const TurtleState& state, uint8_t kind) {
    switch (kind) {
    case 1: return state.position;
    case 2: return state.heading;
    case 3: return state.left;
    default: return state.up;
    }
}

} // namespace

bool hasQueries(const Grammar& grammar) {
    const std::optional<SymbolId> question = grammar.symbols.find("?");
    if (!question) return false;
    const std::vector<uint8_t> kinds = queryKinds(grammar.symbols);
    if (holdsQuery(grammar.axiom, *question, kinds)) return true;
    for (const ProductionSet* set : {&grammar.rules, &grammar.decomposition})
        for (const Production& production : set->productions)
            if (holdsQuery(production.successor, *question, kinds)) return true;
    return false;
}

void answerQueries(const Grammar& grammar, ModuleString& string) {
    const std::optional<SymbolId> question = grammar.symbols.find("?");
    if (!question || !string.hasParameters()) return;
    const std::vector<uint8_t> kinds = queryKinds(grammar.symbols);
    const std::vector<TurtleCommand> commands = turtleCommands(grammar.symbols, grammar.style.cpfgModules);
    const TurtleSettings settings = turtleSettings(grammar);
    const SurfaceLibrary noSurfaces;
    PlantAssetBuilder builder(noSurfaces);
    TurtleState state = initialTurtleState(settings);
    TurtleStack stack;
    for (size_t i = 0; i < string.size(); ++i) {
        const SymbolId symbol = string.symbols[i];
        if (symbol == *question && i + 1 < string.size() && kinds[string.symbols[i + 1]]) {
            const glm::vec3 value = answer(state, kinds[string.symbols[i + 1]]);
            float* parameters = string.params.data() + string.paramStart[i + 1];
            for (uint32_t k = 0; k < std::min<uint32_t>(string.paramCount(i + 1), 3); ++k) parameters[k] = value[k];
            ++i; // the queried module is the answer, not a command
            continue;
        }
        const TurtleCommand& command = commands[symbol];
        if (command.action == TurtleAction::Cut) { // the rest of the branch is not there: skip to its ']'
            i = endOfBranch(string, i + 1) - 1;
            continue;
        }
        if (command.action == TurtleAction::Surface) continue; // no geometry is kept: no mesh is read
        applyModule(command, string.parameters(i), settings, state, stack, builder);
    }
}

} // namespace lsys
