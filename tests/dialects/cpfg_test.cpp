// The cpfg dialect (lsystem/dialects/cpfg.cpp): cpfg's line structure and
// section headers read as cpfg reads them (Měch 2005, §5.1), problems
// reported at their place in the cpfg file, and .l files read as cpfg.

#include <filesystem>
#include <fstream>
#include <memory>

#include "dialect_test_support.h"
#include "lsystem/turtle/turtle_commands.h"
#include "lsystem/vlab/function_file.h"

namespace lsys::test {
namespace {

// cpfg's lexer reads a newline followed by a tab as white space: the
// production goes on over its tab-indented lines.
TEST(Cpfg, ALineStartingWithATabContinuesTheStatementAbove) {
    const std::string oneLine = "Axiom: A\nA --> F[+A][-A]B\nB --> FB\n";
    const std::string continued = "Axiom: A\nA --> F[+A]\n\t[-A]\n\tB\nB --> FB\n";
    const Grammar expected = parseOk(Dialect::Native, oneLine);
    const Grammar grammar = parseOk(Dialect::Cpfg, continued);
    EXPECT_EQ(derived(grammar, 3), derived(expected, 3));
    EXPECT_EQ(grammar.rules.productions.size(), expected.rules.productions.size());
    // Natively the tab-indented lines are statements of their own.
    EXPECT_FALSE(parseDialect(Dialect::Native, continued).ok());
}

TEST(Cpfg, AProblemOnAContinuationLineIsReportedThere) {
    const ParseResult result = parseDialect(Dialect::Cpfg, "Axiom: A\nA --> F\n\tB(1\nB --> F\n", {"tree.l"});
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics.front().file, "tree.l");
    EXPECT_EQ(result.diagnostics.front().line, 3) << result.diagnostics.front().message;
    EXPECT_EQ(result.diagnostics.front().column, 5) << result.diagnostics.front().message; // past "B(1"
}

// Section headers as cpfg accepts them: no colon, a capital letter, cpfg's
// warnings switch, the maximum depth on the same or the next line.
TEST(Cpfg, SectionHeadersInCpfgsSpellings) {
    const std::string source = "Derivationlength: 2\n"
                               "Axiom: A\n"
                               "A --> AB\n"
                               "decomposition\n"
                               "maximum depth: 3\n"
                               "B --> C\n"
                               "Homomorphism: no warnings\n"
                               "C --> F\n"
                               "endlsystem\n";
    const Grammar grammar = parseOk(Dialect::Cpfg, source);
    EXPECT_EQ(grammar.derivationLength, 2);
    EXPECT_EQ(grammar.decomposition.productions.size(), 1u);
    EXPECT_EQ(grammar.decomposition.maxDepth, 3);
    EXPECT_EQ(grammar.interpretation.productions.size(), 1u);
    for (const char* header : {"homomorphism", "homomorphism:", "Homomorphism warnings", "homomorphism no warnings",
                               "homomorphism: warnings maximum depth: 2"}) {
        const Grammar g = parseOk(Dialect::Cpfg, std::string("Axiom: A\n") + header + "\nA --> F\n");
        EXPECT_EQ(g.interpretation.productions.size(), 1u) << header;
        EXPECT_TRUE(g.rules.productions.empty()) << header;
    }
    // A word that only starts like a header is not one.
    EXPECT_FALSE(parseDialect(Dialect::Cpfg, "Axiom: A\nhomomorphisms\nA --> F\n").ok());
    EXPECT_FALSE(parseDialect(Dialect::Cpfg, "Axiom: A\nhomomorphism: maybe warnings\nA --> F\n").ok());
}

TEST(Cpfg, TheDialectIsNamedOrTakenFromTheExtension) {
    EXPECT_EQ(dialectFromName("CPFG"), Dialect::Cpfg);
    EXPECT_EQ(detectDialect("/* dialect: cpfg */\nAxiom: A\n"), Dialect::Cpfg);
    EXPECT_EQ(dialectOfFile(std::nullopt, "Axiom: A\n", "objects/tree/plant.l"), Dialect::Cpfg);
    EXPECT_EQ(dialectOfFile(std::nullopt, "Axiom: A\n", "plant.lsys"), Dialect::Native);
    EXPECT_EQ(dialectOfFile(std::nullopt, "dialect: robbins\nA\n", "plant.l"), Dialect::Robbins);
    EXPECT_EQ(dialectOfFile(Dialect::Native, "Axiom: A\n", "plant.l"), Dialect::Native);

    const std::filesystem::path file = std::filesystem::temp_directory_path() / "plantfield_cpfg_test.l";
    std::ofstream(file) << "Axiom: A\nA --> F\n\tB\nhomomorphism\nB --> F\n";
    const ParseResult result = loadDialectFile(file.string());
    std::filesystem::remove(file);
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, "");
    EXPECT_EQ(derived(result.grammar, 1), "FB");
}

} // namespace
} // namespace lsys::test

namespace lsys::test {
namespace {

// cpfg's blocks may span lines (its grammar allows blank lines and one
// statement per line inside the braces); braces in successors stay polygons.
TEST(Cpfg, StatementBlocksSpanLines) {
    const std::string source = "Start: {\n"
                               "    n = 0;\n"
                               "}\n"
                               "Axiom: A A\n"
                               "A : {\n"
                               "    n = n + 1;\n"
                               "\n"
                               "  } n > 1 --> B(n) {.F.F.}\n"
                               "A --> C(n)\n";
    const Grammar grammar = parseOk(Dialect::Cpfg, source);
    EXPECT_EQ(derived(grammar, 1), "C(1)B(2){.F.F.}");
    const ParseResult open = parseDialect(Dialect::Cpfg, "Axiom: A\nA : {\n x = 1;\n --> B\n", {"plant.l"});
    ASSERT_FALSE(open.diagnostics.empty());
    EXPECT_EQ(open.diagnostics[0].line, 4);
}

// A cpfg file computes as cpfg does: angles in degrees, x/0 = x.
TEST(Cpfg, ExpressionsUseCpfgsArithmetic) {
    EXPECT_EQ(derived(parseOk(Dialect::Cpfg, "Axiom: A\nA --> B(sin(30), 2/0, 7%4)\n"), 1), "B(0.5,2,3)");
}

// cpfg's preprocessor reports a line that begins with '#' but no directive
// and passes it on as text, and cpfg reads it as a production: so is it read
// here, with a warning at its place. A malformed directive is still an error.
TEST(Cpfg, ALineBeginningWithHashButNoDirectiveIsPassedOn) {
    const std::string source = "#define W 1\nAxiom: #(W) A\n#(w) --> #(w + W)\nA --> B\n\t# F\n";
    const ParseResult result = parseDialect(Dialect::Cpfg, source, {"width.l"});
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    EXPECT_EQ(derived(result.grammar, 2), "#(3)B#F");
    ASSERT_EQ(result.warnings.size(), 2u) << formatDiagnostics(result.warnings, source);
    const std::string warning = formatDiagnostic(result.warnings[0], source);
    EXPECT_NE(warning.find("width.l:3:1: warning: '#' begins a line but no directive"), std::string::npos) << warning;
    EXPECT_EQ(result.warnings[1].line, 5);
    EXPECT_EQ(result.warnings[1].column, 2);
    EXPECT_FALSE(parseDialect(Dialect::Cpfg, "#define\nAxiom: A\n").ok());
}

// cpfg matches a strict predecessor of several modules module for module,
// a bracket like any other (generate.c): "B [" rewrites a B with a branch
// right after it, bracket included, and the successor's "[" replaces it, so
// the brackets balance. Natively brackets are no part of a strict predecessor.
TEST(Cpfg, AStrictPredecessorMayHoldABracket) {
    const std::string source = "Axiom: B[A]B A B[[A]]\nB [ --> C [ -\nA ] --> D ]\n";
    const ParseResult result = parseDialect(Dialect::Cpfg, source);
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    EXPECT_TRUE(result.warnings.empty()) << formatDiagnostics(result.warnings, source);
    EXPECT_EQ(derived(result.grammar, 1), "C[-D]BAC[-[D]]");
    EXPECT_FALSE(parseDialect(Dialect::Native, source).ok());
}

// cpfg decomposes what each step makes, never the axiom (generate.c,
// ApplyProd): at 0 steps the axiom is as written.
TEST(Cpfg, TheAxiomIsNotDecomposed) {
    const Grammar grammar = parseOk(Dialect::Cpfg, "Axiom: R(2)\ndecomposition\nmaximum depth: 5\n"
                                                   "R(n) : n > 0 --> R(n - 1) C(n)\n");
    EXPECT_FALSE(grammar.decomposeAxiom);
    EXPECT_EQ(derived(grammar, 0), "R(2)");
    EXPECT_EQ(derived(grammar, 1), "R(0)C(1)C(2)");
}

} // namespace
} // namespace lsys::test

namespace lsys::test {
namespace {

// "//" is a comment in cpfg too, which cuts ABOP's roll runs: a warning says
// so where it happens; unbalanced brackets in a successor get one as well.
TEST(Cpfg, WarningsForCommentsThatCutAProductionAndUnbalancedBrackets) {
    const ParseResult result = parseDialect(Dialect::Cpfg,
                                            "Axiom: A\n"
                                            "A --> F/////F // this comment is fine\n"
                                            "B --> F[+F\n"
                                            "/* // */ C --> D\n",
                                            {"rolls.l"});
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, "");
    EXPECT_EQ(derived(result.grammar, 1), "F");
    ASSERT_EQ(result.warnings.size(), 2u) << formatDiagnostics(result.warnings, "");
    EXPECT_EQ(result.warnings[0].line, 2);
    EXPECT_EQ(result.warnings[0].column, 8);
    EXPECT_NE(formatDiagnostic(result.warnings[0], "").find("rolls.l:2:8: warning: '//' starts a comment"),
              std::string::npos);
    EXPECT_EQ(result.warnings[1].line, 3);
    EXPECT_NE(result.warnings[1].message.find("brackets do not balance (1 '[' and 0 ']')"), std::string::npos);
}

} // namespace
} // namespace lsys::test

namespace lsys::test {
namespace {

// cpfg's func(id, x) with the functions a view file names ("function:
// length.func 100", "function: pos.func"): in a production's block and
// successor, its id a #define, computed as cpfg computes it. The expected
// string is cpfg's own (cpfg 6.6, -str), its numbers printed with %g.
TEST(Cpfg, FuncReadsTheObjectsFunctionFiles) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "plantfield_cpfg_func";
    std::filesystem::create_directories(folder);
    // vlab's TexturedSurfaces/leaf-length.func and LeafPosition/int-pos.func.
    std::ofstream(folder / "length.func") << "range: 0.000000 1.000000\npoints: 4\n0.000000 0.000000\n"
                                             "0.298370 0.004547\n0.304622 0.998629\n1.000000 1.003176\n";
    std::ofstream(folder / "pos.func") << "fver 1 1\nname: int-pos\nsamples: 10\nflip: off\npoints: 4\n"
                                          "0.000000 1.013734 1\n0.230453 0.561893 1\n0.778895 0.452828 1\n"
                                          "1.000000 0.209768 1\n";
    std::vector<vlab::VlabFunction> functions;
    for (const auto& [file, samples] : {std::pair{"length.func", 100}, std::pair{"pos.func", -1}})
        functions.push_back(vlab::readFunctionFile(folder / file, samples).function);
    std::filesystem::remove_all(folder);
    const std::string source = "#define POSITION 2\n"
                               "Lsystem: 1\n"
                               "derivation length: 4\n"
                               "Axiom: A(0)\n"
                               "A(x) : { y = func(1, x) * 10; } 1 --> F(y) B(func(POSITION, x), func(1, 1 - x)) "
                               "A(x + 0.3)\n"
                               "endlsystem\n";
    ParseOptions options;
    options.file = "plant.l";
    options.functions = vlab::functionTable(std::move(functions));
    const ParseResult result = parseDialect(Dialect::Cpfg, source, options);
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    const char* const cpfg = "F(0.000161505)B(1.01241,1.00317)F(3.95827)B(0.669997,0.924674)F(8.52323)"
                             "B(0.478295,0.593562)F(9.95227)B(0.296165,0.0434781)A(1.2)";
    const std::optional<std::string> difference =
        firstDifference(deriveSteps(result.grammar, 4), result.grammar.symbols, cpfg, 1e-5);
    EXPECT_FALSE(difference) << *difference;

    // Without the table func is an error at its place; so is an id past its end.
    const ParseResult none = parseDialect(Dialect::Cpfg, source, {"plant.l"});
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.diagnostics[0].line, 5);
    EXPECT_EQ(none.diagnostics[0].column, 14);
    options.functions = vlab::functionTable(std::vector<vlab::VlabFunction>(1));
    const ParseResult tooFew = parseDialect(Dialect::Cpfg, source, options);
    ASSERT_FALSE(tooFew.ok());
    EXPECT_EQ(tooFew.diagnostics[0].line, 5);
    EXPECT_NE(tooFew.diagnostics[0].message.find("names 1 function"), std::string::npos)
        << tooFew.diagnostics[0].message;
}

// cpfg reads '@!(6)' as the modules '@' and '!(6)' (lsys_input.l reads one
// character per name), so its production of '!' rewrites the '!' of '@!(6)'
// too; here '@!' is one module. The difference is warned of at the
// production, never silent; a file without '@!' gets no warning.
TEST(Cpfg, AProductionOfAModuleThatAnAtModuleEndsWithIsWarnedOf) {
    const std::string source = "Axiom: !(2) @!(6) F\n!(w) --> !(w - 1)\nF --> FF\n";
    const ParseResult result = parseDialect(Dialect::Cpfg, source, {"at.l"});
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    EXPECT_EQ(derived(result.grammar, 1), "!(1)@!(6)FF");
    ASSERT_EQ(result.warnings.size(), 1u) << formatDiagnostics(result.warnings, source);
    const std::string warning = formatDiagnostic(result.warnings[0], source);
    EXPECT_NE(warning.find("at.l:2:1: warning: cpfg reads '@!' as two modules, '@' and '!'"), std::string::npos)
        << warning;
    EXPECT_TRUE(parseDialect(Dialect::Cpfg, "Axiom: !(2) F\n!(w) --> !(w - 1)\n").warnings.empty());
}

// cpfg's $ ends a sub-L-system (interpret.c, '$'), and one that ends none is
// skipped: in cpfg files it is no roll, @v is. A production that starts a
// sub-L-system, which plantfield does not read, is warned of.
TEST(Cpfg, DollarIsNoRollAndSubLsystemsAreWarnedOf) {
    const std::string source = "Axiom: A\nA --> F ?(2, 1.5) B $ F\n";
    const ParseResult result = parseDialect(Dialect::Cpfg, source, {"sub.l"});
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    ASSERT_EQ(result.warnings.size(), 1u) << formatDiagnostics(result.warnings, source);
    const std::string warning = formatDiagnostic(result.warnings[0], source);
    EXPECT_NE(warning.find("sub.l:2:1: warning: cpfg's sub-L-systems"), std::string::npos) << warning;
    const auto command = [&](const char* name) { return turtleCommand(name, result.grammar.style.cpfgModules).action; };
    EXPECT_EQ(command("$"), TurtleAction::None);
    EXPECT_EQ(command("@v"), TurtleAction::RollHorizontal);
    EXPECT_EQ(turtleCommand("$").action, TurtleAction::RollHorizontal);                            // native files roll
    EXPECT_TRUE(parseDialect(Dialect::Cpfg, "Axiom: A\nA --> F ?P(0, 0) $ F\n").warnings.empty()); // a query
}

} // namespace
} // namespace lsys::test
