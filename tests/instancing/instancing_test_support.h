#pragma once
// Helpers shared by the b-grammar tests: the plant files, word comparison,
// and an expansion of single nodes that does not use the library's.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../lsystem/test_support.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/vlab/object.h"

namespace lsys::test {

// Every plant of data/plants and its folders (files and vlab objects), relative to data/.
inline std::vector<std::string> allPlantFiles() {
    const std::filesystem::path root = dataPath("");
    std::vector<std::string> files;
    for (const std::filesystem::path& plant : vlab::findPlants(root / "plants"))
        files.push_back(plant.lexically_relative(root).string());
    return files;
}

// Same modules with the same parameter values, in the same order.
inline void expectSameWord(const ModuleString& actual, const ModuleString& expected, const SymbolTable& symbols) {
    ASSERT_EQ(actual.size(), expected.size());
    bool same = actual.symbols == expected.symbols;
    for (size_t i = 0; same && i < actual.size(); ++i) {
        std::span<const float> a = actual.parameters(i), b = expected.parameters(i);
        same = std::equal(a.begin(), a.end(), b.begin(), b.end());
    }
    if (!same && actual.size() < 2000) {
        EXPECT_EQ(toString(actual, symbols), toString(expected, symbols));
    }
    EXPECT_TRUE(same) << "the words differ";
}

// Modules per symbol of a word, counted one by one.
inline std::vector<uint64_t> histogram(const ModuleString& word, size_t symbolCount) {
    std::vector<uint64_t> counts(symbolCount, 0);
    for (SymbolId symbol : word.symbols) ++counts[symbol];
    return counts;
}

// The symbols a node expands to, walked recursively here rather than by expand().
inline void appendNodeWord(const BGrammar& grammar, uint32_t node, std::vector<SymbolId>& out) {
    for (const BodyItem& item : grammar.bodyOf(node)) {
        if (item.isNode()) {
            appendNodeWord(grammar, item.index, out);
        } else {
            out.push_back(grammar.modules[item.index].symbol);
        }
    }
}

// Legality as the Calgary b-grammar thesis defines it: no prefix of the node's
// word has more ']' than '['.
inline bool nodeIsLegal(const BGrammar& grammar, uint32_t node) {
    std::vector<SymbolId> word;
    appendNodeWord(grammar, node, word);
    int depth = 0;
    for (SymbolId symbol : word) {
        depth += symbol == kPush ? 1 : symbol == kPop ? -1 : 0;
        if (depth < 0) return false;
    }
    return true;
}

// How many times each node is referenced over all bodies.
inline std::vector<uint32_t> referenceCounts(const BGrammar& grammar) {
    std::vector<uint32_t> uses(grammar.nodes.size(), 0);
    for (const BodyItem& item : grammar.body)
        if (item.isNode()) ++uses[item.index];
    return uses;
}

} // namespace lsys::test
