#include "engine/field/field_scopes.h"

namespace pf {
namespace {

// Each scope at its enum's index, with a name.
constexpr bool everyScopeIsDefined() {
    for (size_t i = 0; i < kFieldScopes.size(); ++i)
        if (size_t(kFieldScopes[i].scope) != i || kFieldScopes[i].name == nullptr ||
            std::string_view(kFieldScopes[i].name).empty())
            return false;
    return size_t(FieldScope::antialias) + 1 == kFieldScopes.size();
}
static_assert(everyScopeIsDefined(), "every FieldScope needs its definition, in enum order");

// The colour pass opens "colour" and records the nested scopes inside it
// before it closes: they are those recorded after it.
constexpr bool nestedScopesFollowColor() {
    for (size_t i = 0; i < kFieldScopes.size(); ++i)
        if (kFieldScopes[i].insideColor != (i > size_t(FieldScope::color))) return false;
    return true;
}
static_assert(nestedScopesFollowColor(), "the scopes inside \"colour\" are those after it");

// The tools key their columns and JSON by name.
constexpr bool namesAreUnique() {
    for (size_t a = 0; a < kFieldScopes.size(); ++a)
        for (size_t b = a + 1; b < kFieldScopes.size(); ++b)
            if (std::string_view(kFieldScopes[a].name) == kFieldScopes[b].name) return false;
    return true;
}
static_assert(namesAreUnique(), "two field scopes share a name");

} // namespace

std::optional<FieldScope> fieldScopeNamed(std::string_view name) {
    for (const FieldScopeDefinition& definition : kFieldScopes)
        if (name == definition.name) return definition.scope;
    return std::nullopt;
}

TimedFieldScope::TimedFieldScope(VkCommandBuffer cmd, GpuTimer* timer, FieldScope scope, ScopeStart start)
    : TimedScope(cmd, timer, fieldScope(scope).name, start) {}

} // namespace pf
