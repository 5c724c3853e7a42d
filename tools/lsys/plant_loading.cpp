#include "tools/lsys/plant_loading.h"

#include <cstdlib>
#include <iostream>
#include <unordered_map>

#include "lsystem/error.h"
#include "lsystem/parser.h"
#include "lsystem/vlab/object.h"

namespace tools {
namespace {

// Parses "NAME=VALUE" items of -D into constants; reports malformed ones.
bool parseDefines(const std::vector<std::string>& items, std::unordered_map<std::string, double>& out) {
    for (const std::string& item : items) {
        size_t equals = item.find('=');
        char* end = nullptr;
        double value = equals == std::string::npos ? 0.0 : std::strtod(item.c_str() + equals + 1, &end);
        if (equals == std::string::npos || equals == 0 || end == item.c_str() + equals + 1 || *end != '\0') {
            std::cerr << "lsys: error: -D expects NAME=NUMBER, got '" << item << "'\n";
            return false;
        }
        out[item.substr(0, equals)] = value;
    }
    return true;
}

} // namespace

std::optional<lsys::Grammar> loadGrammar(const std::string& file, const std::optional<lsys::Dialect>& dialect,
                                         const std::vector<std::string>& defines) {
    lsys::ParseOptions options;
    options.file = file;
    if (!parseDefines(defines, options.defines)) return std::nullopt;
    lsys::vlab::PlantFile plant = lsys::vlab::loadPlant(file, dialect, options);
    lsys::ParseResult& result = plant.parsed;
    std::cerr << lsys::formatDiagnostics(result.warnings, plant.source);
    if (!result.ok()) {
        std::cerr << lsys::formatDiagnostics(result.diagnostics, plant.source);
        std::cerr << result.diagnostics.size() << (result.diagnostics.size() == 1 ? " error\n" : " errors\n");
        return std::nullopt;
    }
    return std::move(result.grammar);
}

} // namespace tools
