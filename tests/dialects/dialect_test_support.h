#pragma once
// Helpers shared by the dialect tests: load a dialect or native file, derive,
// and look at the result as canonical text or symbol counts.

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "lsystem/dialects/dialect.h"
#include "lsystem/language/module_string.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/vlab/object.h"

namespace lsys::test {

inline std::string dataPath(const std::string& relative) { return std::string(PLANTFIELD_DATA_DIR) + "/" + relative; }

// Loads a file of any dialect (named by its header line); fails the test on any diagnostic.
inline Grammar loadOk(const std::string& relative) {
    vlab::PlantFile plant = vlab::loadPlant(dataPath(relative));
    EXPECT_TRUE(plant.parsed.ok()) << relative << ":\n" << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    return std::move(plant.parsed.grammar);
}

inline Grammar parseOk(Dialect dialect, const std::string& source) {
    ParseResult result = parseDialect(dialect, source);
    EXPECT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    return std::move(result.grammar);
}

inline ModuleString deriveSteps(const Grammar& grammar, int steps, uint64_t seed = 0) {
    DeriveOptions options;
    options.steps = steps;
    options.seed = seed;
    return derive(grammar, options);
}

inline std::string derived(const Grammar& grammar, int steps) {
    return toString(deriveSteps(grammar, steps), grammar.symbols);
}

inline std::map<std::string, size_t> countsOf(const ModuleString& string, const Grammar& grammar) {
    std::map<std::string, size_t> counts;
    for (size_t i = 0; i < string.size(); ++i) ++counts[grammar.symbols.name(string.symbols[i])];
    return counts;
}

} // namespace lsys::test
