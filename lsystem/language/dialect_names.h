#pragma once
// The notations a plant file may be written in, and their names as a file's
// "dialect: NAME" line, lsys --dialect and the Python module's dialect= give
// them. The native parser lists them in its message for a dialect line it
// cannot read; lsystem/dialects/dialect.h reads each notation.

#include <optional>
#include <string>
#include <string_view>

namespace lsys {

enum class Dialect { Native, Crankshaw, Robbins, Plantlang, Cpfg };

// "native", "crankshaw", "robbins", "plantlang", "cpfg" (case-insensitive).
std::optional<Dialect> dialectFromName(std::string_view name);
const char* dialectName(Dialect dialect);
std::string knownDialects(); // "native, crankshaw, robbins, plantlang or cpfg", for messages

} // namespace lsys
