// lsys: derive and check .lsys files from the command line.
//   lsys derive FILE [-n STEPS] [--seed S] [-D NAME=VALUE]... [--dialect D] [--print] [--json] [--max-modules N]
//   lsys check FILE [-D NAME=VALUE]... [--dialect D]
// Exit codes: 0 success, 2 bad input (parse errors, budget exceeded), 1 usage errors.

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lsystem/dialects/dialect.h"
#include "lsystem/error.h"
#include "lsystem/parser.h"
#include "lsystem/rewriter.h"

namespace {

constexpr int kBadInput = 2;

struct Arguments {
    std::string file;
    std::optional<int> steps;
    std::optional<uint64_t> seed;
    std::vector<std::string> defines;
    std::optional<lsys::Dialect> dialect;  // none: the file's "dialect:" line, else native
    bool print = false;
    bool json = false;
    size_t maxModules = 50'000'000;
    int threads = 2;
};

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

// Parses the file; on problems prints them all and returns nullopt.
std::optional<lsys::Grammar> load(const Arguments& arguments) {
    lsys::ParseOptions options;
    options.file = arguments.file;
    if (!parseDefines(arguments.defines, options.defines)) return std::nullopt;
    bool readable = false;
    std::string source = lsys::readTextFile(arguments.file, readable);
    if (!readable) {
        std::cerr << arguments.file << ": error: cannot read file\n";
        return std::nullopt;
    }
    lsys::ParseResult result = lsys::parseDialect(arguments.dialect, source, options);
    if (!result.ok()) {
        std::cerr << lsys::formatDiagnostics(result.diagnostics, source);
        std::cerr << result.diagnostics.size() << (result.diagnostics.size() == 1 ? " error\n" : " errors\n");
        return std::nullopt;
    }
    return std::move(result.grammar);
}

int derive(const Arguments& arguments) {
    std::optional<lsys::Grammar> grammar = load(arguments);
    if (!grammar) return kBadInput;
    lsys::DeriveOptions options;
    options.steps = arguments.steps;
    options.seed = arguments.seed;
    options.maxModules = arguments.maxModules;
    options.threads = arguments.threads;
    auto start = std::chrono::steady_clock::now();
    lsys::ModuleString string;
    try {
        string = lsys::derive(*grammar, options);
    } catch (const lsys::DerivationError& error) {
        std::cerr << arguments.file << ": error: " << error.what() << '\n';
        return kBadInput;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int steps = options.steps.value_or(grammar->derivationLength);

    if (arguments.print) {
        std::string text = lsys::toString(string, grammar->symbols);
        std::fwrite(text.data(), 1, text.size(), stdout);
        std::fputc('\n', stdout);
    }
    if (arguments.json) {
        std::vector<size_t> counts(grammar->symbols.size(), 0);
        for (lsys::SymbolId symbol : string.symbols) ++counts[symbol];
        nlohmann::json countsJson = nlohmann::json::object();
        for (size_t id = 0; id < counts.size(); ++id)
            if (counts[id]) countsJson[grammar->symbols.name(static_cast<lsys::SymbolId>(id))] = counts[id];
        nlohmann::json out = {{"modules", string.size()}, {"steps", steps}, {"counts", countsJson}, {"seconds", seconds}};
        std::cout << out.dump() << '\n';
    }
    if (!arguments.print && !arguments.json)
        std::cout << string.size() << " modules after " << steps << " steps\n";
    return 0;
}

// --dialect NAME, any case; an unknown name is a usage error (exit code 2).
void addDialectOption(CLI::App& command, Arguments& arguments) {
    command
        .add_option_function<std::string>(
            "--dialect", [&arguments](const std::string& name) { arguments.dialect = lsys::dialectFromName(name); },
            "Input notation: " + lsys::knownDialects() + " (default: the file's 'dialect:' line, else native)")
        ->check([](const std::string& name) {
            return lsys::dialectFromName(name) ? std::string() : "unknown dialect '" + name + "' (expected " + lsys::knownDialects() + ")";
        });
}

int check(const Arguments& arguments) {
    if (!load(arguments)) return kBadInput;
    std::cout << arguments.file << ": ok\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lsys: derive and check L-systems written in the .lsys notation or a dialect (docs/DIALECTS.md)"};
    app.require_subcommand(1);
    Arguments arguments;

    CLI::App* deriveCommand = app.add_subcommand("derive", "Derive an L-system and report, print or count the result");
    deriveCommand->add_option("FILE", arguments.file, ".lsys file")->required();
    deriveCommand->add_option("-n,--steps", arguments.steps, "Derivation steps (default: the file's 'derivation length:')");
    deriveCommand->add_option("--seed", arguments.seed, "Random seed (default: the file's 'seed:')");
    deriveCommand->add_option("-D,--define", arguments.defines, "Override a #define constant: NAME=VALUE (repeatable)");
    addDialectOption(*deriveCommand, arguments);
    deriveCommand->add_flag("--print", arguments.print, "Print the final string, e.g. F(1,0.5)[+A(2)]");
    deriveCommand->add_flag("--json", arguments.json, "Print {\"modules\", \"steps\", \"counts\", \"seconds\"} as JSON");
    deriveCommand->add_option("--max-modules", arguments.maxModules, "Module budget; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    deriveCommand->add_option("--threads", arguments.threads, "Rewriting threads")->check(CLI::Range(1, 64));

    CLI::App* checkCommand = app.add_subcommand("check", "Parse a file and report every problem without deriving");
    checkCommand->add_option("FILE", arguments.file, ".lsys file")->required();
    checkCommand->add_option("-D,--define", arguments.defines, "Override a #define constant: NAME=VALUE (repeatable)");
    addDialectOption(*checkCommand, arguments);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : kBadInput;
    }
    if (deriveCommand->parsed()) return derive(arguments);
    return check(arguments);
}
