// The turtle's commands as a table for --help, printed from their
// definitions (lsystem/turtle/turtle_commands.cpp), so the help cannot disagree
// with what the turtle does.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/turtle/turtle_commands.h"

namespace lsys {

std::string turtleCommandHelp() {
    struct Row {
        std::string symbol, parameters;
        std::string_view documentation;
    };
    std::vector<Row> rows;
    size_t symbolWidth = 6, parameterWidth = 10; // the headings
    for (const TurtleCommandDefinition& definition : turtleCommandDefinitions())
        for (std::string_view symbol : {definition.symbol, definition.alias}) {
            if (symbol.empty()) continue;
            // A prefix is shown with the name it is followed by: ~name.
            rows.push_back({std::string(symbol) + (definition.symbolIsPrefix ? "name" : ""),
                            std::string(definition.parameters), definition.documentation});
            symbolWidth = std::max(symbolWidth, rows.back().symbol.size());
            parameterWidth = std::max(parameterWidth, rows.back().parameters.size());
        }
    auto line = [&](std::string_view symbol, std::string_view parameters, std::string_view documentation) {
        std::string text(symbol);
        text.resize(symbolWidth + 2, ' ');
        text.append(parameters).resize(symbolWidth + 2 + parameterWidth + 2, ' ');
        return text.append(documentation).append("\n");
    };
    std::string help =
        "The turtle's commands (docs/LSYS_FORMAT.md, \"Turtle\"). Angles are in degrees, widths are diameters;\n"
        "a parameter left out is what follows its '='.\n\n";
    help += line("symbol", "parameters", "what it does");
    for (const Row& row : rows) help += line(row.symbol, row.parameters, row.documentation);
    return help;
}

} // namespace lsys
