#include "lsystem/language/symbols.h"

#include <stdexcept>

namespace lsys {

SymbolTable::SymbolTable() {
    intern("[");
    intern("]");
    intern("=");
}

SymbolId SymbolTable::intern(std::string_view name) {
    std::string key(name);
    if (auto found = ids.find(key); found != ids.end()) return found->second;
    if (names.size() > UINT16_MAX) throw std::length_error("too many distinct module names");
    SymbolId id = static_cast<SymbolId>(names.size());
    names.push_back(key);
    ids.emplace(std::move(key), id);
    return id;
}

std::optional<SymbolId> SymbolTable::find(std::string_view name) const {
    if (auto found = ids.find(std::string(name)); found != ids.end()) return found->second;
    return std::nullopt;
}

} // namespace lsys
