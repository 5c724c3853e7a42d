#pragma once
// Interned module names: the rewriter compares small integers, never strings.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lsys {

using SymbolId = uint16_t;

// Brackets (and '=') are interned first in every table so the hot loops can
// test them against constants.
inline constexpr SymbolId kPush = 0; // [
inline constexpr SymbolId kPop = 1;  // ]
// '=' in a right context skips the rest of the current branch, up to its ']'
// (cpfg's context rule; Měch 2005, §5.1).
inline constexpr SymbolId kSkipBranch = 2;

struct SymbolTable {
    std::vector<std::string> names;
    std::unordered_map<std::string, SymbolId> ids;

    SymbolTable();
    // Returns the id of name, adding it if new. Throws std::length_error past 65 535 names.
    SymbolId intern(std::string_view name);
    std::optional<SymbolId> find(std::string_view name) const;
    const std::string& name(SymbolId id) const { return names[id]; }
    size_t size() const { return names.size(); }
};

} // namespace lsys
