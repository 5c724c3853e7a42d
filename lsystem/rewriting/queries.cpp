#include "lsystem/rewriting/queries.h"

#include "lsystem/language/query_modules.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys {

namespace {

// Whether module i is a '?' followed by a queried module.
bool isQuery(const ModuleString& string, size_t i, SymbolId question, const std::vector<uint8_t>& kinds) {
    return string.symbols[i] == question && i + 1 < string.size() && kinds[string.symbols[i + 1]];
}

// cpfg's up vector is L x H, ours H x L (lsystem/turtle/turtle_frame.h): a cpfg
// file's ?U answers its own (interpret.c, '?').
glm::vec3 answer(const TurtleState& state, uint8_t kind, bool cpfg) {
    switch (kind) {
    case 1: return state.position;
    case 2: return state.heading;
    case 3: return state.left;
    default: return cpfg ? -state.up : state.up;
    }
}

// A query of the string answered: its '?' there, and in the string the turtle reads.
struct QueryPlace {
    size_t answered;
    size_t read;
};

// The string the turtle reads to answer the queries: every run of modules
// between two queries through the interpretation rules, the queries as they
// are. cpfg's turtle rewrites each module by the homomorphism as it reads
// it, but a '?' reads the module after it from the string itself and writes
// its answer there (interpret.c, InterpretHomomorphism and InterpretSymbol,
// '?'). Contexts do not reach across a query.
ModuleString throughInterpretation(const Grammar& grammar, const ModuleString& string, SymbolId question,
                                   const std::vector<uint8_t>& kinds, std::vector<QueryPlace>& places) {
    ModuleString read, run;
    auto flush = [&] {
        if (run.empty()) return;
        const ModuleString interpreted = applyInterpretation(grammar, run);
        for (size_t k = 0; k < interpreted.size(); ++k) read.push(interpreted.symbols[k], interpreted.parameters(k));
        run.clear();
    };
    for (size_t i = 0; i < string.size(); ++i) {
        if (!isQuery(string, i, question, kinds)) {
            run.push(string.symbols[i], string.parameters(i));
            continue;
        }
        flush();
        places.push_back({i, read.size()});
        read.push(question);
        read.push(string.symbols[i + 1], string.parameters(i + 1));
        ++i;
    }
    flush();
    return read;
}

} // namespace

void answerQueries(const Grammar& grammar, ModuleString& string) {
    const std::optional<SymbolId> question = grammar.symbols.find("?");
    if (!question || !string.hasParameters()) return;
    const std::vector<uint8_t> kinds = queryKinds(grammar.symbols);
    std::vector<QueryPlace> places;
    ModuleString interpreted;
    if (grammar.interpretation.empty()) {
        for (size_t i = 0; i < string.size(); ++i)
            if (isQuery(string, i, *question, kinds)) places.push_back({i, i});
    } else {
        interpreted = throughInterpretation(grammar, string, *question, kinds, places);
    }
    // Answers go into the queried modules, which the turtle does not read.
    const ModuleString& read = grammar.interpretation.empty() ? string : interpreted;

    const std::vector<TurtleCommand> commands = turtleCommands(grammar.symbols, grammar.style.cpfgModules);
    const TurtleSettings settings = turtleSettings(grammar);
    const SurfaceLibrary noSurfaces;
    PlantAssetBuilder builder(noSurfaces);
    TurtleState state = initialTurtleState(settings);
    TurtleStack stack;
    size_t next = 0; // the first of places not passed yet
    for (size_t i = 0; i < read.size(); ++i) {
        while (next < places.size() && places[next].read < i) ++next; // cut with their branch: unanswered
        if (isQuery(read, i, *question, kinds)) {
            // One the interpretation rules wrote has nowhere to keep its answer.
            if (next < places.size() && places[next].read == i) {
                const size_t queried = places[next].answered + 1;
                const glm::vec3 value = answer(state, kinds[string.symbols[queried]], settings.cpfgModules);
                float* parameters = string.params.data() + string.paramStart[queried];
                for (uint32_t k = 0; k < std::min<uint32_t>(string.paramCount(queried), 3); ++k)
                    parameters[k] = value[k];
            }
            ++i; // the queried module is the answer, not a command
            continue;
        }
        const TurtleCommand& command = commands[read.symbols[i]];
        if (command.action == TurtleAction::Cut) { // the rest of the branch is not there: skip to its ']'
            i = endOfBranch(read, i + 1) - 1;
            continue;
        }
        if (command.action == TurtleAction::Surface) continue; // no geometry is kept: no mesh is read
        applyModule(command, read.parameters(i), settings, state, stack, builder);
    }
}

} // namespace lsys
