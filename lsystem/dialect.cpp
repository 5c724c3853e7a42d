#include "lsystem/dialect.h"

#include <cctype>

#include "lsystem/lexer.h"

namespace lsys {

std::optional<Dialect> dialectByName(std::string_view name) {
    if (name == "native") return Dialect::Native;
    if (name == "crankshaw") return Dialect::Crankshaw;
    if (name == "robbins") return Dialect::Robbins;
    if (name == "plantlang") return Dialect::Plantlang;
    return std::nullopt;
}

std::optional<std::string> declaredDialect(std::string_view source) {
    std::vector<Diagnostic> ignored;
    std::string text = blankComments(source, "", ignored);
    for (std::string_view line : splitLines(text)) {
        Cursor cursor{line, 0, 1};
        cursor.skipSpaces();
        if (cursor.atEnd()) continue;
        if (!cursor.accept("dialect")) return std::nullopt;
        cursor.skipSpaces();
        if (!cursor.accept(":")) return std::nullopt;
        cursor.skipSpaces();
        std::string name;
        while (!cursor.atEnd() && !std::isspace(static_cast<unsigned char>(cursor.peek()))) name += cursor.text[cursor.pos++];
        return name;
    }
    return std::nullopt;
}

Translation translate(Dialect dialect, std::string_view source, const std::string& file) {
    switch (dialect) {
        case Dialect::Crankshaw: return translateCrankshaw(source, file);
        case Dialect::Robbins: return translateRobbins(source, file);
        case Dialect::Plantlang: return translatePlantlang(source, file);
        case Dialect::Native: break;
    }
    return {std::string(source), {}, {}};
}

}  // namespace lsys
