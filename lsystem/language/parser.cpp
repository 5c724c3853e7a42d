#include "lsystem/language/parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include "lsystem/common/file_reader.h"
#include "lsystem/language/dialect_names.h"
#include "lsystem/language/lexer.h"
#include "lsystem/language/production_checks.h"

namespace lsys {

namespace {

// Symbols that are modules on their own (besides letters and digits).
constexpr std::string_view kTurtleSymbols = "+-&^\\/|[]!;$%~'\"{}.?_=#,";

// Case-insensitive "keyword:" at the cursor (after leading spaces); consumes it on success.
bool acceptHeader(Cursor& cursor, std::string_view keyword, bool needsColon = true) {
    size_t save = cursor.pos;
    cursor.skipSpaces();
    for (char k : keyword) {
        if (std::tolower(static_cast<unsigned char>(cursor.peek())) != k) {
            cursor.pos = save;
            return false;
        }
        ++cursor.pos;
    }
    if (isIdentifierChar(cursor.peek()) && isIdentifierChar(keyword.back())) {
        cursor.pos = save;
        return false;
    }
    cursor.skipSpaces();
    if (needsColon && !cursor.accept(":")) {
        cursor.pos = save;
        return false;
    }
    return true;
}

std::string withoutSpaces(std::string_view text) {
    std::string out;
    for (char c : text)
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
    return out;
}

// Headers that choose one of two ways, the first the default (docs/LSYS_FORMAT.md).
struct Choice {
    std::string_view header, first, second;
    void (*set)(Grammar&, bool second);
};
constexpr Choice kChoices[] = {
    // How the expressions after it compute.
    {"arithmetic", "native", "cpfg",
     [](Grammar& g, bool cpfg) { g.arithmetic = cpfg ? Arithmetic::Cpfg : Arithmetic::Native; }},
    {"cut", "this step", "next step", [](Grammar& g, bool next) { g.cutInNextStep = next; }},
    {"decompose axiom", "yes", "no", [](Grammar& g, bool no) { g.decomposeAxiom = !no; }},
    {"turtle modules", "native", "cpfg", [](Grammar& g, bool cpfg) { g.style.cpfgModules = cpfg; }},
    // Before the productions it governs (a bracket in a left context).
    {"context", "native", "cpfg", [](Grammar& g, bool cpfg) { g.cpfgContexts = cpfg; }},
};

struct Parser {
    Grammar& grammar;
    const ParseOptions& options;
    std::vector<Diagnostic>& diagnostics;
    std::vector<Diagnostic>& warnings;
    std::vector<std::string> declared; // multi-letter module names, longest first
    ProductionSet* section = nullptr;
    std::optional<std::vector<SymbolId>> considered;
    std::vector<std::string> signatures[3]; // predecessor text per production, to form stochastic groups
    bool ended = false;
    bool sawAxiom = false;

    const std::string& file() const { return options.file; }
    void error(const Cursor& cursor, std::string message, std::string expected = {}) {
        diagnostics.push_back(errorAt(cursor, file(), std::move(message), std::move(expected)));
    }

    std::vector<std::string>& signaturesOf(const ProductionSet* set) {
        return signatures[set == &grammar.rules ? 0 : set == &grammar.decomposition ? 1 : 2];
    }

    // A module name at the cursor, or empty if none starts here.
    std::string moduleName(Cursor& cursor) {
        char c = cursor.peek();
        size_t begin = cursor.pos;
        if (c == '@' && std::isupper(static_cast<unsigned char>(cursor.peek(1)))) {
            cursor.pos += 2;
            while (std::islower(static_cast<unsigned char>(cursor.peek()))) ++cursor.pos;
            return std::string(cursor.text.substr(begin, cursor.pos - begin));
        }
        // cpfg's other '@' modules: @o @c @v ... (one letter), @mo @bc ... (two), @# @! @; @,
        if (c == '@' && (std::islower(static_cast<unsigned char>(cursor.peek(1))) ||
                         std::string_view("#!;,").find(cursor.peek(1)) != std::string_view::npos)) {
            const char first = cursor.peek(1);
            cursor.pos += 2;
            if ((first == 'm' || first == 'b') && std::islower(static_cast<unsigned char>(cursor.peek()))) ++cursor.pos;
            return std::string(cursor.text.substr(begin, cursor.pos - begin));
        }
        if (c == '~' && isIdentifierStart(cursor.peek(1))) {
            ++cursor.pos;
            cursor.identifier();
            return std::string(cursor.text.substr(begin, cursor.pos - begin));
        }
        if (isIdentifierStart(c))
            for (const std::string& name : declared)
                if (cursor.startsWith(name)) {
                    cursor.pos += name.size();
                    return name;
                }
        if (std::isalnum(static_cast<unsigned char>(c)) ||
            (c != '\0' && kTurtleSymbols.find(c) != std::string_view::npos)) {
            ++cursor.pos;
            return std::string(1, c);
        }
        return {};
    }

    ExpressionScope scopeFor(std::span<const std::string> variables) const {
        return {variables, &grammar.constants, &grammar.globals, grammar.arithmetic, options.functions};
    }

    BlockScope blockScope(std::vector<std::string>* locals, bool arrayDefinitions) {
        return {locals, &grammar.globals, &grammar.constants, grammar.arithmetic, arrayDefinitions, options.functions};
    }

    std::optional<double> constantExpression(Cursor& cursor) {
        ExpressionScope scope{{}, &grammar.constants, nullptr, grammar.arithmetic, options.functions};
        std::optional<Expression> expression = parseExpression(cursor, scope, file(), diagnostics);
        if (!expression) return std::nullopt;
        RandomStream random = RandomStream::forModule(grammar.seed, ~0ull, 0);
        return evaluate(*expression, nullptr, random);
    }

    bool expectLineEnd(Cursor& cursor) {
        cursor.skipSpaces();
        if (cursor.atEnd()) return true;
        error(cursor, std::string("unexpected '") + cursor.peek() + "'", "end of line");
        return false;
    }

    void line(Cursor cursor) {
        cursor.skipSpaces();
        if (cursor.atEnd() || ended) return;
        if (cursor.accept("#define")) return define(cursor);
        // Any other line that begins with '#' is a production of the width
        // module when it has an arrow (cpfg's preprocessor passes it on as text).
        if (cursor.peek() == '#' && cursor.text.find("->") == std::string_view::npos)
            return error(cursor, "unknown directive", "'#define'");
        if (acceptHeader(cursor, "endlsystem", false)) {
            expectLineEnd(cursor);
            ended = true;
            return;
        }
        if (acceptHeader(cursor, "lsystem")) return; // lpfg's "lsystem: 1" names the system; nothing to do
        if (acceptHeader(cursor, "ring lsystem", false)) return void(grammar.ring = expectLineEnd(cursor));
        if (Cursor header = cursor;
            acceptHeader(cursor, "dialect")) // a valid header line never gets here (parseDialect blanks it)
            return error(header, "unknown or misplaced dialect line",
                         "'dialect: NAME' as the first non-blank line, NAME one of " + knownDialects());
        if (acceptHeader(cursor, "seed")) return seed(cursor);
        if (acceptHeader(cursor, "derivation length")) return derivationLength(cursor);
        if (acceptHeader(cursor, "angle")) return number(cursor, grammar.angle);
        if (acceptHeader(cursor, "step")) return number(cursor, grammar.step);
        if (acceptHeader(cursor, "width")) return number(cursor, grammar.width);
        if (acceptHeader(cursor, "ignore")) return contextSymbols(cursor, false);
        if (acceptHeader(cursor, "consider")) return contextSymbols(cursor, true);
        if (acceptHeader(cursor, "axiom")) return axiom(cursor);
        for (const Choice& choice : kChoices)
            if (acceptHeader(cursor, choice.header)) return choose(cursor, choice);
        if (acceptHeader(cursor, "define")) return globalBlock(cursor, nullptr);
        if (acceptHeader(cursor, "start each") || acceptHeader(cursor, "starteach"))
            return globalBlock(cursor, &grammar.startEachBlock);
        if (acceptHeader(cursor, "end each") || acceptHeader(cursor, "endeach"))
            return globalBlock(cursor, &grammar.endEachBlock);
        if (acceptHeader(cursor, "start")) return globalBlock(cursor, &grammar.startBlock);
        if (acceptHeader(cursor, "end")) return globalBlock(cursor, &grammar.endBlock);
        if (acceptHeader(cursor, "maximum depth")) return maximumDepth(cursor);
        if (acceptHeader(cursor, "production") || acceptHeader(cursor, "productions"))
            return beginSection(cursor, grammar.rules);
        if (acceptHeader(cursor, "decomposition")) return beginSection(cursor, grammar.decomposition);
        if (acceptHeader(cursor, "interpretation") || acceptHeader(cursor, "homomorphism"))
            return beginSection(cursor, grammar.interpretation);
        if (acceptHeader(cursor, "module", false) || acceptHeader(cursor, "modules", false))
            return declareModules(cursor);
        if (cursor.text.find("->") != std::string_view::npos) return production(cursor);
        error(cursor, "unrecognised line",
              "a header such as 'Axiom:', a production 'predecessor --> successor' or '#define'");
    }

    void define(Cursor& cursor) {
        cursor.skipSpaces();
        std::string name(cursor.identifier());
        if (name.empty()) return error(cursor, "missing constant name after #define", "a name");
        std::optional<double> value = constantExpression(cursor);
        if (!value || !expectLineEnd(cursor)) return;
        // A value given on the command line (-D) wins over the file.
        if (!options.defines.contains(name)) grammar.constants[name] = *value;
    }

    void seed(Cursor& cursor) {
        cursor.skipSpaces();
        Cursor start = cursor;
        std::optional<double> value = constantExpression(cursor);
        if (!value || !expectLineEnd(cursor)) return;
        if (!(*value >= 0) || *value != std::floor(*value) || *value > 1.8e19)
            return error(start, "invalid seed", "a non-negative integer");
        grammar.seed = static_cast<uint64_t>(*value);
    }

    void derivationLength(Cursor& cursor) {
        cursor.skipSpaces();
        Cursor start = cursor;
        std::optional<double> value = constantExpression(cursor);
        if (!value || !expectLineEnd(cursor)) return;
        if (!(*value >= 0) || *value != std::floor(*value) || *value > kMaxDerivationLength)
            return error(start, "invalid derivation length", "a non-negative integer");
        grammar.derivationLength = static_cast<int>(*value);
    }

    void maximumDepth(Cursor& cursor) {
        cursor.skipSpaces();
        Cursor start = cursor;
        std::optional<double> value = constantExpression(cursor);
        if (!value || !expectLineEnd(cursor)) return;
        if (!section || section == &grammar.rules)
            return error(start, "'maximum depth:' outside a decomposition or interpretation section");
        // vlab's objects ask for up to 3000 passes (LilyLeaf); each pass ends
        // the section early once no production applies.
        if (!(*value >= 1) || *value != std::floor(*value) || *value > 10000)
            return error(start, "invalid maximum depth", "an integer from 1 to 10000");
        section->maxDepth = static_cast<int>(*value);
    }

    void number(Cursor& cursor, double& target) {
        cursor.skipSpaces();
        std::optional<double> value = constantExpression(cursor);
        if (value && expectLineEnd(cursor)) target = *value;
    }

    void contextSymbols(Cursor& cursor, bool consider) {
        if (consider && !considered) considered.emplace();
        while (true) {
            cursor.skipSpaces();
            if (cursor.atEnd()) return;
            std::string name = moduleName(cursor);
            if (name.empty()) return error(cursor, std::string("unexpected '") + cursor.peek() + "'", "a module name");
            SymbolId symbol = grammar.symbols.intern(name);
            if (consider) {
                considered->push_back(symbol);
            } else {
                grammar.ignored.resize(grammar.symbols.size(), 0);
                grammar.ignored[symbol] = 1;
            }
        }
    }

    void declareModules(Cursor& cursor) {
        while (true) {
            cursor.skipSpaces();
            if (cursor.atEnd()) break;
            std::string name(cursor.identifier());
            if (name.empty()) return error(cursor, std::string("unexpected '") + cursor.peek() + "'", "a module name");
            if (std::find(declared.begin(), declared.end(), name) == declared.end()) declared.push_back(name);
            grammar.symbols.intern(name);
            cursor.skipSpaces();
            if (cursor.accept("(")) { // L-Py allows "module Apex(age)": the parameter names are documentation
                while (!cursor.atEnd() && cursor.peek() != ')') ++cursor.pos;
                if (!cursor.accept(")")) return error(cursor, "unclosed parameter list", "')'");
                cursor.skipSpaces();
            }
            if (!cursor.accept(",") && !cursor.atEnd() && !isIdentifierStart(cursor.peek()))
                return error(cursor, std::string("unexpected '") + cursor.peek() + "'", "',' or another module name");
        }
        std::stable_sort(declared.begin(), declared.end(),
                         [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
    }

    // "header: value", one of the two values a Choice names.
    void choose(Cursor& cursor, const Choice& choice) {
        cursor.skipSpaces();
        for (const bool second : {false, true})
            if (acceptHeader(cursor, second ? choice.second : choice.first, false)) {
                if (expectLineEnd(cursor)) choice.set(grammar, second);
                return;
            }
        error(cursor, "unknown " + std::string(choice.header) + " setting",
              "'" + std::string(choice.first) + "' or '" + std::string(choice.second) + "'");
    }

    // "start: { ... }" and the like; "define: { array ...; }" (into = null) only defines arrays.
    void globalBlock(Cursor& cursor, Block* into) {
        BlockScope scope = blockScope(nullptr, into == nullptr);
        std::optional<Block> block = parseBlock(cursor, scope, file(), diagnostics);
        if (!block || !expectLineEnd(cursor)) return;
        if (into) into->insert(into->end(), block->begin(), block->end());
    }

    // A production's block before or after its condition, when one starts at the cursor.
    bool productionBlock(Cursor& cursor, Production& production, Block& into) {
        cursor.skipSpaces();
        if (cursor.peek() != '{') return true;
        BlockScope scope = blockScope(&production.variables, false);
        std::optional<Block> block = parseBlock(cursor, scope, file(), diagnostics);
        if (!block) return false;
        into = std::move(*block);
        return true;
    }

    void beginSection(Cursor& cursor, ProductionSet& set) {
        section = &set;
        if (acceptHeader(cursor, "maximum depth")) return maximumDepth(cursor);
        expectLineEnd(cursor);
    }

    // Modules with argument expressions, until the end of the line or a ':' (probability).
    bool successorModules(Cursor& cursor, std::span<const std::string> variables, std::vector<SuccessorModule>& out) {
        const ExpressionScope scope = scopeFor(variables);
        cursor.skipSpaces();
        if (cursor.peek() == '*') { // cpfg's explicit empty successor
            ++cursor.pos;
            return true;
        }
        while (true) {
            cursor.skipSpaces();
            if (cursor.atEnd() || cursor.peek() == ':') return true;
            std::string name = moduleName(cursor);
            if (name.empty()) {
                error(cursor, std::string("unexpected '") + cursor.peek() + "'", "a module");
                return false;
            }
            SuccessorModule module{grammar.symbols.intern(name), {}};
            if (cursor.accept("(")) {
                cursor.skipSpaces();
                while (!cursor.accept(")")) {
                    if (!module.arguments.empty() && !cursor.accept(",")) {
                        error(cursor, "malformed parameter list", "',' or ')'");
                        return false;
                    }
                    std::optional<Expression> argument = parseExpression(cursor, scope, file(), diagnostics);
                    if (!argument) return false;
                    module.arguments.push_back(std::move(*argument));
                    cursor.skipSpaces();
                    if (module.arguments.size() > 255) {
                        error(cursor, "too many parameters");
                        return false;
                    }
                }
            }
            out.push_back(std::move(module));
        }
    }

    void axiom(Cursor& cursor) {
        std::vector<SuccessorModule> modules;
        if (!successorModules(cursor, {}, modules) || !expectLineEnd(cursor)) return;
        grammar.axiom = std::move(modules);
        sawAxiom = true;
    }

    bool patternModule(Cursor& cursor, Production& production, std::vector<PatternModule>& out) {
        std::string name = moduleName(cursor);
        if (name.empty()) {
            error(cursor, std::string("unexpected '") + cursor.peek() + "' in predecessor",
                  "a module, '<', '>', ':' or '-->'");
            return false;
        }
        PatternModule module{grammar.symbols.intern(name), 0, static_cast<uint16_t>(production.variables.size())};
        if (cursor.accept("(")) {
            while (true) {
                cursor.skipSpaces();
                if (cursor.accept(")")) break;
                if (module.paramCount > 0 && !cursor.accept(",")) {
                    error(cursor, "malformed parameter list", "',' or ')'");
                    return false;
                }
                cursor.skipSpaces();
                std::string_view formal = cursor.identifier();
                if (formal.empty()) {
                    error(cursor, "a predecessor parameter must be a name", "a name such as 'x'");
                    return false;
                }
                if (production.variables.size() >= kMaxVariables) {
                    error(cursor, "too many parameters in one production");
                    return false;
                }
                production.variables.emplace_back(formal);
                ++module.paramCount;
            }
        }
        out.push_back(module);
        return true;
    }

    void production(Cursor& cursor) {
        if (!section) section = &grammar.rules;
        Production production;
        production.line = cursor.line;
        cursor.skipSpaces();
        size_t labelStart = cursor.pos;
        std::string_view label = cursor.identifier();
        cursor.skipSpaces();
        if (label.size() >= 2 && std::find(declared.begin(), declared.end(), label) == declared.end() &&
            cursor.accept(":"))
            production.label = label;
        else
            cursor.pos = labelStart;

        // Predecessor: [left <] strict [> right]
        cursor.skipSpaces();
        size_t predecessorStart = cursor.pos;
        std::vector<PatternModule> before, strict, after;
        std::vector<PatternModule>* current = &before;
        Cursor leftMark = cursor;
        bool sawLeft = false;
        while (true) {
            cursor.skipSpaces();
            if (cursor.atEnd()) return error(cursor, "production has no arrow", "'-->'");
            if (cursor.atArrow() || cursor.peek() == ':') break;
            if (cursor.peek() == '<') {
                if (sawLeft || current == &after)
                    return error(cursor, "misplaced '<'", "one left context before the strict predecessor");
                sawLeft = true;
                leftMark = cursor;
                ++cursor.pos;
                current = &strict;
                continue;
            }
            if (cursor.peek() == '*') { // cpfg's explicit empty context: "* < A", "A > *"
                if (!((current == &before && before.empty()) || (current == &after && after.empty())))
                    return error(cursor, "'*' stands for a whole context",
                                 "'* < strict' or 'strict > *' (no context), or a module");
                ++cursor.pos;
                cursor.skipSpaces();
                if (current == &before && cursor.peek() != '<')
                    return error(cursor, "'*' is an empty left context, so '<' must follow", "'<'");
                continue;
            }
            if (cursor.peek() == '>') {
                if (current == &after) return error(cursor, "second '>' in predecessor", "one right context");
                ++cursor.pos;
                if (!sawLeft) std::swap(before, strict);
                current = &after;
                continue;
            }
            if (!patternModule(cursor, production, *current)) return;
        }
        if (!sawLeft && current != &after) std::swap(before, strict);
        production.left = std::move(before);
        production.right = std::move(after);
        if (strict.empty())
            return error(cursor, "predecessor has no strict module", "a module, with optional '<' and '>' contexts");
        // cpfg matches a strict predecessor of several modules module for
        // module from where it starts, a bracket like any other (generate.c).
        for (const PatternModule& module : strict)
            if ((module.symbol == kPush || module.symbol == kPop) && !(grammar.cpfgContexts && strict.size() > 1))
                return error(cursor, "brackets are not allowed in a strict predecessor", "modules only");
        production.strict = strict[0];
        production.strictTail.assign(strict.begin() + 1, strict.end());
        for (const PatternModule& module : production.left) {
            if (module.symbol != kPush && module.symbol != kPop) continue;
            if (!grammar.cpfgContexts)
                return error(leftMark, "brackets are not allowed in a left context",
                             "modules only; the left context climbs branches by itself");
            // cpfg accepts it, and its left context never stops on a bracket (generate.c, LconDiff).
            warnings.push_back({file(),
                                production.line,
                                1,
                                "a bracket in a left context never matches: the production never applies",
                                {},
                                {},
                                Severity::Warning});
            break;
        }
        std::string signature = withoutSpaces(cursor.text.substr(predecessorStart, cursor.pos - predecessorStart));

        production.formalCount = static_cast<uint16_t>(production.variables.size());
        if (cursor.accept(":")) { // [{ before }] condition [{ after }], cpfg's statement blocks around the condition
            cursor.skipSpaces();
            size_t conditionStart = cursor.pos;
            if (!productionBlock(cursor, production, production.before)) return;
            cursor.skipSpaces();
            const size_t expressionStart = cursor.pos;
            if (cursor.accept("*") && (cursor.skipSpaces(), cursor.atArrow() || cursor.peek() == '{')) {
                // "*" means no condition (cpfg)
            } else {
                cursor.pos = expressionStart;
                production.condition = parseExpression(cursor, scopeFor(production.variables), file(), diagnostics);
                if (!production.condition) return;
            }
            if (!productionBlock(cursor, production, production.after)) return;
            signature += ":" + withoutSpaces(cursor.text.substr(conditionStart, cursor.pos - conditionStart));
            cursor.skipSpaces();
        }
        if (!cursor.accept("-->") && !cursor.accept("->"))
            return error(cursor, "missing arrow after predecessor", "'-->' or '->'");
        if (!successorModules(cursor, production.variables, production.successor)) return;
        if (cursor.accept(":")) {
            cursor.skipSpaces();
            Cursor start = cursor;
            std::optional<double> probability = constantExpression(cursor);
            if (!probability) return;
            if (!(*probability >= 0 && *probability <= 1))
                return error(start, "probability out of range", "a number from 0 to 1");
            production.stochastic = true;
            production.probability = *probability;
        }
        if (!expectLineEnd(cursor)) return;
        section->productions.push_back(std::move(production));
        signaturesOf(section).push_back(std::move(signature));
    }

    void finish() {
        for (auto& [name, value] : options.defines) grammar.constants[name] = value;
        for (ProductionSet* set : {&grammar.rules, &grammar.decomposition, &grammar.interpretation}) {
            warnOfUnbalancedBrackets(*set, file(), warnings);
            warnOfCpfgAtModules(grammar, *set, file(), warnings);
            warnOfCpfgSubLsystems(grammar, *set, file(), warnings);
            formStochasticGroups(*set, signaturesOf(set), file(), diagnostics);
        }
        finalizeGrammar(grammar);
        if (considered) {
            std::fill(grammar.ignored.begin(), grammar.ignored.end(), 1);
            // lpfg's consider: counts the brackets; cpfg's ignores them unless listed (lsys_input.y).
            if (!grammar.cpfgContexts) grammar.ignored[kPush] = grammar.ignored[kPop] = 0;
            for (SymbolId symbol : *considered) grammar.ignored[symbol] = 0;
        }
    }
};

} // namespace

ParseResult parseLsystem(std::string_view source, const ParseOptions& options) {
    ParseResult result;
    result.grammar.file = options.file;
    for (auto& [name, value] : options.defines) result.grammar.constants[name] = value;
    Parser parser{result.grammar, options, result.diagnostics, result.warnings};
    std::string text = blankComments(source, options.file, result.diagnostics);
    std::vector<std::string_view> lines = splitLines(text);
    for (size_t i = 0; i < lines.size(); ++i) {
        try {
            parser.line(Cursor{lines[i], 0, static_cast<int>(i) + 1});
        } catch (const std::length_error& error) { // symbol table full
            result.diagnostics.push_back({options.file, static_cast<int>(i) + 1, 1, error.what()});
            break;
        }
    }
    parser.finish();
    if (!parser.sawAxiom && result.diagnostics.empty())
        result.diagnostics.push_back({options.file, 1, 1, "no axiom", "an 'Axiom:' line"});
    sortBySourcePosition(result.diagnostics);
    sortBySourcePosition(result.warnings);
    return result;
}

std::string readTextFile(const std::string& path, std::string& problem) {
    FileBytes file = readFileUpTo(path, kMaxSourceBytes);
    problem = file.problem == FileProblem::Folder ? "is a folder, not a plant file"
                                                  : fileProblemText(file.problem, kMaxSourceBytes);
    return std::move(file.bytes);
}

} // namespace lsys
