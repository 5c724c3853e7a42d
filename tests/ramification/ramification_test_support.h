#pragma once
// Helpers shared by the ramification tests: plants from L-system text or data files.

#include <gtest/gtest.h>

#include <string>

#include "lsystem/parser.h"
#include "lsystem/rewriter.h"
#include "lsystem/surfaces.h"
#include "lsystem/turtle.h"
#include "lsystem/vlab/object.h"

namespace lsys::test {

inline std::string dataPath(const std::string& relative) { return std::string(PLANTFIELD_DATA_DIR) + "/" + relative; }
inline std::string testDataPath(const std::string& name) { return std::string(RAMIFICATION_TEST_DATA) + "/" + name; }

// The plant a file (an L-system or a vlab object) draws after its derivation length.
inline PlantAsset plantOfFile(const std::string& path) {
    vlab::PlantFile plant = vlab::loadPlant(path);
    EXPECT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    const Grammar& grammar = plant.parsed.grammar;
    return plantFromGrammar(grammar, derive(grammar), SurfaceLibrary(meshDirectoriesFor(path)));
}

// The plant the axiom `word` draws.
inline PlantAsset plantOfWord(const std::string& word) {
    const std::string source = "derivation length: 0\nAxiom: " + word + "\n";
    ParseResult parsed = parseLsystem(source);
    EXPECT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, source);
    return plantFromGrammar(parsed.grammar, derive(parsed.grammar));
}

} // namespace lsys::test
