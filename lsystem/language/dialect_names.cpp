#include "lsystem/language/dialect_names.h"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace lsys {

namespace {

constexpr const char* kNames[] = {"native", "crankshaw", "robbins", "plantlang", "cpfg"};

} // namespace

std::optional<Dialect> dialectFromName(std::string_view name) {
    for (size_t i = 0; i < std::size(kNames); ++i) {
        std::string_view candidate = kNames[i];
        if (candidate.size() == name.size() &&
            std::equal(name.begin(), name.end(), candidate.begin(),
                       [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
            return static_cast<Dialect>(i);
    }
    return std::nullopt;
}

const char* dialectName(Dialect dialect) { return kNames[static_cast<size_t>(dialect)]; }

std::string knownDialects() {
    std::string list = kNames[0];
    for (size_t i = 1; i < std::size(kNames); ++i)
        list += (i + 1 < std::size(kNames) ? ", " : " or ") + std::string(kNames[i]);
    return list;
}

} // namespace lsys
