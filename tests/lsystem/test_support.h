#pragma once
// Helpers shared by the lsystem tests: parse text or a data file, derive, and
// look at the result as canonical text or symbol counts.

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "lsystem/dialects/dialect.h"
#include "lsystem/language/parser.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/vlab/object.h"

namespace lsys::test {

inline std::string dataPath(const std::string& relative) { return std::string(PLANTFIELD_DATA_DIR) + "/" + relative; }

// Parses source and fails the test (showing the diagnostics) if it has errors.
inline Grammar parseOk(const std::string& source, const ParseOptions& options = {}) {
    ParseResult result = parseLsystem(source, options);
    EXPECT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    return std::move(result.grammar);
}

// A plant of data/ (a file, or a vlab object folder) that must load.
inline Grammar loadOk(const std::string& relative) {
    vlab::PlantFile plant = vlab::loadPlant(dataPath(relative));
    ParseResult& result = plant.parsed;
    EXPECT_TRUE(result.ok()) << relative << ": " << formatDiagnostics(result.diagnostics, plant.source);
    return std::move(result.grammar);
}

inline DeriveOptions stepsOf(int steps) {
    DeriveOptions options;
    options.steps = steps;
    return options;
}

// The derived string in canonical form after the given number of steps.
inline std::string derived(const std::string& source, int steps) {
    Grammar grammar = parseOk(source);
    return toString(derive(grammar, stepsOf(steps)), grammar.symbols);
}

inline size_t countOf(const ModuleString& string, const Grammar& grammar, const std::string& name) {
    std::optional<SymbolId> id = grammar.symbols.find(name);
    if (!id) return 0;
    size_t count = 0;
    for (SymbolId symbol : string.symbols) count += symbol == *id;
    return count;
}

} // namespace lsys::test
