// The table of turtle commands (lsystem/turtle/turtle_commands.h): the names the
// turtle resolves and the help it prints both come from it.

#include <algorithm>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "turtle_test_support.h"

namespace lsys::test {
namespace {

TEST(LsysTurtleCommands, EveryDefinedSymbolNamesItsCommand) {
    for (const TurtleCommandDefinition& definition : turtleCommandDefinitions()) {
        for (std::string_view symbol : {definition.symbol, definition.alias}) {
            if (symbol.empty()) continue;
            const std::string name = std::string(symbol) + (definition.symbolIsPrefix ? "leaf" : "");
            const TurtleCommand command = turtleCommand(name, true);
            // cpfg's $ ends a sub-L-system: no command in its files.
            const bool notInCpfg = definition.symbolNotInCpfg && symbol == definition.symbol;
            EXPECT_EQ(command.action, notInCpfg ? TurtleAction::None : definition.action) << name;
            // cpfg's own commands are ordinary modules elsewhere.
            EXPECT_EQ(turtleCommand(name).action, definition.cpfgOnly ? TurtleAction::None : definition.action) << name;
            EXPECT_EQ(command.surface, definition.symbolIsPrefix ? "leaf" : "") << name;
        }
    }
    EXPECT_EQ(turtleCommand("A").action, TurtleAction::None);
    EXPECT_EQ(turtleCommand("~").action, TurtleAction::None); // a surface needs a name
}

TEST(LsysTurtleCommands, TheHelpHasARowForEverySymbol) {
    std::istringstream help(turtleCommandHelp());
    std::vector<std::string> firstWords;
    for (std::string line; std::getline(help, line);) firstWords.push_back(line.substr(0, line.find(' ')));
    for (const TurtleCommandDefinition& definition : turtleCommandDefinitions()) {
        for (std::string_view symbol : {definition.symbol, definition.alias}) {
            if (symbol.empty()) continue;
            const std::string shown = std::string(symbol) + (definition.symbolIsPrefix ? "name" : "");
            EXPECT_NE(std::find(firstWords.begin(), firstWords.end(), shown), firstWords.end()) << shown;
        }
    }
}

TEST(LsysTurtleCommands, FInsideAPolygonActsAsSmallF) {
    EXPECT_EQ(actingDefinition(TurtleAction::Draw, 0).action, TurtleAction::Draw);
    EXPECT_EQ(actingDefinition(TurtleAction::Draw, 1).action, TurtleAction::Move);
    EXPECT_EQ(actingDefinition(TurtleAction::Move, 1).action, TurtleAction::Move);
    EXPECT_EQ(parameterCount(turtleCommandDefinition(TurtleAction::Draw)), 2u);
    EXPECT_EQ(parameterCount(turtleCommandDefinition(TurtleAction::TropismVector)), 3u);
    EXPECT_EQ(parameterCount(turtleCommandDefinition(TurtleAction::TurnAround)), 0u);
}

TEST(LsysTurtleCommands, ANonFiniteParameterStopsTheTurtleNamingTheCommand) {
    for (const char* source : {"Axiom: F(1) F(0/0)\n", "Axiom: F(1) +(1/0) F(1)\n", "Axiom: !(0/0) F(1)\n"}) {
        SCOPED_TRACE(source);
        try {
            (void)plantOf(source);
            ADD_FAILURE() << "a plant was built";
        } catch (const DerivationError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("the turtle's"), std::string::npos) << message;
            EXPECT_TRUE(message.find("NaN") != std::string::npos || message.find("infinite") != std::string::npos)
                << message;
        }
    }
    // A module that is no command may carry anything.
    EXPECT_EQ(plantOf("Axiom: A(0/0) F(1)\n").primitives.size(), 1u);
}

// Each step finite, their sum not: stopped at the step that passes the float
// range, not exported as infinities.
TEST(LsysTurtleCommands, StepsAddingUpPastTheFloatRangeStopTheTurtleNamingTheCommand) {
    try {
        (void)plantOf("Axiom: F(3e38) f(3e38) F(1)\n");
        ADD_FAILURE() << "a plant was built";
    } catch (const DerivationError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "the turtle's f moved it past the float range: its position is no longer a finite number");
    }
}

} // namespace
} // namespace lsys::test
