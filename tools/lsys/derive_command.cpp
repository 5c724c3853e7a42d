#include "tools/lsys/derive_command.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "lsystem/language/parser.h"
#include "lsystem/rewriting/rewriter.h"
#include "tools/lsys/plant_loading.h"

namespace tools {

namespace {

struct DeriveArguments : DerivationArguments {
    bool print = false;
    std::string printFormat = "text"; // --format: "text" or "cpfg"
    std::string compareWith;          // --compare: a string file to compare the derived string with
    bool json = false;
    int threads = 2;
};

// --compare: the derived string against a string file (cpfg's -str output, or --print's).
int compare(const DeriveArguments& arguments, const lsys::Grammar& grammar, const lsys::ModuleString& string) {
    std::string problem;
    const std::string text = lsys::readTextFile(arguments.compareWith, problem);
    if (!problem.empty()) {
        std::cerr << arguments.compareWith << ": error: cannot read file: it " << problem << "\n";
        return kBadInput;
    }
    if (std::optional<std::string> difference = lsys::firstDifference(string, grammar.symbols, text)) {
        std::cout << arguments.compareWith << " differs: " << *difference << "\n";
        return 1;
    }
    std::cout << arguments.compareWith << " is the same string: " << string.size()
              << " modules, parameters within 1e-4 relative\n";
    return 0;
}

int runDerive(const DeriveArguments& arguments) {
    std::optional<lsys::Grammar> grammar = loadGrammar(arguments);
    if (!grammar) return kBadInput;
    lsys::DeriveOptions options = deriveOptions(arguments);
    options.threads = arguments.threads;
    auto start = std::chrono::steady_clock::now();
    lsys::ModuleString string;
    try {
        string = lsys::derive(*grammar, options);
    } catch (const lsys::DerivationError& error) {
        return failed(arguments, error);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int steps = options.steps.value_or(grammar->derivationLength);

    if (!arguments.compareWith.empty()) return compare(arguments, *grammar, string);
    if (arguments.print) {
        const bool cpfg = arguments.printFormat == "cpfg";
        lsys::writeText(string, grammar->symbols, cpfg ? lsys::TextLayout::Cpfg : lsys::TextLayout::OneLine,
                        [](std::string_view chunk) { std::fwrite(chunk.data(), 1, chunk.size(), stdout); });
        if (!cpfg) std::fputc('\n', stdout);
    }
    if (arguments.json) {
        nlohmann::json countsJson = nlohmann::json::object();
        for (const auto& [name, count] : lsys::moduleCounts(string, grammar->symbols)) countsJson[name] = count;
        nlohmann::json out = {
            {"modules", string.size()}, {"steps", steps}, {"counts", countsJson}, {"seconds", seconds}};
        std::cout << out.dump() << '\n';
    }
    if (!arguments.print && !arguments.json) std::cout << string.size() << " modules after " << steps << " steps\n";
    return 0;
}

} // namespace

Command addDeriveCommand(CLI::App& app) {
    auto arguments = std::make_shared<DeriveArguments>();
    CLI::App* command = app.add_subcommand("derive", "Derive an L-system and report, print or count the result");
    addDerivationOptions(*command, *arguments);
    command->add_flag("--print", arguments->print, "Print the final string, e.g. F(1,0.5)[+A(2)]");
    command
        ->add_option("--format", arguments->printFormat,
                     "How --print writes the string: text (on one line) or cpfg (as cpfg's -str writes it: a line "
                     "break before a module once 70 characters are on the line)")
        ->check(CLI::IsMember({"text", "cpfg"}));
    command->add_option("--compare", arguments->compareWith,
                        "Compare the derived string with a string file (cpfg's -str output, or --print's): "
                        "module for module, parameters within 1e-4 relative; exit status 1 when they differ");
    command->add_flag("--json", arguments->json, "Print {\"modules\", \"steps\", \"counts\", \"seconds\"} as JSON");
    command->add_option("--max-modules", arguments->maxModules, "Module budget; exceeding it is an error")
        ->check(CLI::PositiveNumber);
    command->add_option("--threads", arguments->threads, "Rewriting threads")->check(CLI::Range(1, 64));
    return {command, [arguments] { return runDerive(*arguments); }};
}

} // namespace tools
