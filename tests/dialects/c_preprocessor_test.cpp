// cpfg files go through the C preprocessor first, as cpfg runs vlabcpp on
// them (Měch 2005, §5.1): macros, conditionals and #include work, and every
// problem is reported at its file, line and column in the user's files.

#include <filesystem>
#include <fstream>

#include "dialect_test_support.h"
#include "lsystem/dialects/c_preprocessor.h"
#include "lsystem/language/lexer.h"

namespace lsys::test {
namespace {

// A fresh folder of files for one test, removed afterwards.
struct Folder {
    std::filesystem::path path;
    explicit Folder(const std::string& name)
        : path(std::filesystem::temp_directory_path() / ("plantfield_cpp_" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~Folder() { std::filesystem::remove_all(path); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return (path / name).string();
    }
};

TEST(CPreprocessor, MacrosAndConditionalsExpandAsInCpfg) {
    const std::string source = "#define R 2\n"
                               "#define grow(x) ((x) * R)\n"
                               "#if R > 1\n"
                               "#define SIDE [+A]\n"
                               "#else\n"
                               "#define SIDE [-A]\n"
                               "#endif\n"
                               "Axiom: A\n"
                               "A --> F(grow(1 + 2)) SIDE /* a comment */ B\n"
                               "B --> C // cut, as cpfg's preprocessor cuts it\n";
    const Grammar grammar = parseOk(Dialect::Cpfg, source);
    EXPECT_EQ(derived(grammar, 1), "F(6)[+A]B");
    EXPECT_EQ(derived(grammar, 2), "F(6)[+F(6)[+A]B]C");
    // "$" is a turtle module, not part of a name: the macro before it expands.
    EXPECT_EQ(derived(parseOk(Dialect::Cpfg, "#define T +F\nAxiom: A\nA --> T$T\n"), 1), "+F$+F");
    // No macros are predefined: "unix" and "linux" stay names.
    EXPECT_FALSE(parseDialect(Dialect::Cpfg, "Axiom: A\nA --> F(unix)\n").ok());
}

TEST(CPreprocessor, TabContinuationSurvivesPreprocessing) {
    const Grammar grammar = parseOk(Dialect::Cpfg, "#define N 3\nAxiom: A\nA --> F(N)\n\t[+A]\n\tB\n");
    EXPECT_EQ(derived(grammar, 1), "F(3)[+A]B");
}

TEST(CPreprocessor, IncludedFilesAreReadAndTheirProblemsNamedThere) {
    const Folder folder("include");
    folder.write("shared.h", "#define ANGLE 30\n/* a rule kept apart */\nB --> F(2)\n");
    const std::string plant = folder.write("plant.l", "#include \"shared.h\"\nAxiom: A\nA --> +(ANGLE)B\n");
    const ParseResult good = loadDialectFile(plant);
    ASSERT_TRUE(good.ok()) << formatDiagnostics(good.diagnostics, "");
    EXPECT_EQ(derived(good.grammar, 2), "+(30)F(2)");

    folder.write("shared.h", "#define ANGLE 30\n/* a rule kept apart */\nB --> F(2\n");
    const ParseResult bad = loadDialectFile(plant);
    ASSERT_EQ(bad.diagnostics.size(), 1u) << formatDiagnostics(bad.diagnostics, "");
    EXPECT_EQ(bad.diagnostics[0].file, (folder.path / "shared.h").string());
    EXPECT_EQ(bad.diagnostics[0].line, 3);
    EXPECT_EQ(bad.diagnostics[0].column, 10); // where "F(2" ends
    // The quoted line is the included file's, not the plant file's line 3.
    EXPECT_NE(
        formatDiagnostics(bad.diagnostics, "#include \"shared.h\"\nAxiom: A\nA --> +(ANGLE)B\n").find("  B --> F(2\n"),
        std::string::npos);
}

TEST(CPreprocessor, PreprocessorErrorsAreLocated) {
    const ParseResult missing = parseDialect(Dialect::Cpfg, "Axiom: A\n#include \"none.h\"\n", {"plant.l"});
    ASSERT_EQ(missing.diagnostics.size(), 1u);
    EXPECT_EQ(missing.diagnostics[0].file, "plant.l");
    EXPECT_EQ(missing.diagnostics[0].line, 2);
    EXPECT_EQ(missing.diagnostics[0].column, 10);
    EXPECT_NE(missing.diagnostics[0].message.find("none.h"), std::string::npos);

    const ParseResult unclosed = parseDialect(Dialect::Cpfg, "Axiom: A\n#if 1\nA --> B\n", {"plant.l"});
    ASSERT_EQ(unclosed.diagnostics.size(), 1u);
    EXPECT_EQ(unclosed.diagnostics[0].line, 2);
    EXPECT_NE(unclosed.diagnostics[0].message.find("unterminated #if"), std::string::npos);

    // No directive: passed on as text, as vlabcpp does, and read by what follows.
    const ParseResult bogus = parseDialect(Dialect::Cpfg, "Axiom: A\n#bogus\n", {"plant.l"});
    ASSERT_EQ(bogus.diagnostics.size(), 1u);
    EXPECT_EQ(bogus.diagnostics[0].line, 2);
    EXPECT_EQ(bogus.diagnostics[0].column, 1);
    EXPECT_EQ(derived(parseOk(Dialect::Cpfg, "#define W 2\nAxiom: A\nA --> F\n\t#(W) F\n"), 1), "F#(2)F");
}

// cpp writes comments as one space, collapses runs of spaces and replaces
// macros by their text; problems are still shown where the user wrote them.
TEST(CPreprocessor, ColumnsAreTheUsersAfterCommentsSpacesAndMacros) {
    const ParseResult result =
        parseDialect(Dialect::Cpfg, "#define L 1\nAxiom: A\nA -->   F(L) /* long comment */  G(L) $ B(L,\n");
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics[0].line, 3);
    EXPECT_EQ(result.diagnostics[0].column, 45) << result.diagnostics[0].message; // just past "B(L,"
    const ParseResult inMacro = parseDialect(Dialect::Cpfg, "#define BAD F(\nAxiom: A\nA --> G  BAD\n");
    ASSERT_FALSE(inMacro.diagnostics.empty());
    EXPECT_EQ(inMacro.diagnostics[0].line, 3);
    EXPECT_EQ(inMacro.diagnostics[0].column, 10); // the macro's name stands for its text
}

TEST(CPreprocessor, DefinesFromOutsideReplaceTheFilesOrAreAdded) {
    const std::string source = "#define R 2\nAxiom: A\nA --> F(R) G(S)\n";
    ParseOptions options;
    options.defines = {{"R", 5}, {"S", 0.25}};
    const ParseResult result = parseDialect(Dialect::Cpfg, source, options);
    ASSERT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    EXPECT_EQ(derived(result.grammar, 1), "F(5)G(0.25)");
}

// vlabcpp, like every C preprocessor, reads ' as the start of a character
// constant that runs to the end of the line, so nothing after it expands:
// cpfg does the same, and the name is reported where it stands.
TEST(CPreprocessor, NothingExpandsAfterAnApostropheAsInCpfg) {
    const std::string source = "#define W 3\nAxiom: A\nA --> F(W)'F(W)\n";
    const ParseResult result = parseDialect(Dialect::Cpfg, source);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 3);
    EXPECT_EQ(result.diagnostics[0].column, 14);
    EXPECT_NE(result.diagnostics[0].message.find("'W'"), std::string::npos);
}

TEST(CPreprocessor, AMissingPreprocessorIsAClearError) {
    PreprocessOptions options;
    options.program = "plantfield-no-such-preprocessor";
    const PreprocessedText text = runCPreprocessor("Axiom: A\n", "plant.l", options);
    ASSERT_EQ(text.diagnostics.size(), 1u);
    EXPECT_EQ(text.diagnostics[0].file, "plant.l");
    EXPECT_NE(text.diagnostics[0].message.find("plantfield-no-such-preprocessor"), std::string::npos);
    EXPECT_NE(text.diagnostics[0].message.find("package cpp"), std::string::npos);
}

// A preprocessor reading a device without end is stopped by its memory
// limit, not the machine's: a clear error, quickly.
TEST(CPreprocessor, AnEndlessIncludeIsAnErrorNotAnExhaustedMachine) {
    const ParseResult result = parseDialect(Dialect::Cpfg, "#include \"/dev/zero\"\nAxiom: A\n", {"plant.l"});
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].file, "plant.l");
    EXPECT_NE(result.diagnostics[0].message.find("the C preprocessor failed (it may use 1024 MiB)"), std::string::npos)
        << result.diagnostics[0].message;
}

TEST(CPreprocessor, OutputLinesKnowTheirFileAndLine) {
    const Folder folder("origins");
    folder.write("two.h", "X --> Y\nY --> Z\n");
    const PreprocessedText text = runCPreprocessor("Axiom: A\n#include \"two.h\"\n\n\n\n\n\n\n\n\n\n\n\nA --> B\n",
                                                   (folder.path / "plant.l").string(), {});
    ASSERT_TRUE(text.diagnostics.empty());
    std::vector<std::pair<std::string, int>> found;
    const std::vector<std::string_view> lines = splitLines(text.text);
    ASSERT_EQ(lines.size(), text.lines.size());
    for (size_t i = 0; i < lines.size(); ++i)
        if (!lines[i].empty())
            found.emplace_back(std::filesystem::path(text.files[text.lines[i].file]).filename(), text.lines[i].line);
    const std::vector<std::pair<std::string, int>> expected{
        {"plant.l", 1}, {"two.h", 1}, {"two.h", 2}, {"plant.l", 14}};
    EXPECT_EQ(found, expected);
}

} // namespace
} // namespace lsys::test
