#include "tools/lsys/plant_loading.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <unordered_map>

#include "lsystem/common/error.h"
#include "lsystem/language/parser.h"
#include "lsystem/vlab/object.h"
#include "tools/memory_budget_option.h"

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

void addPlantFileOptions(CLI::App& command, DerivationArguments& arguments) {
    command.add_option("FILE", arguments.file, "plant file (.lsys, .l, any dialect) or vlab object folder")->required();
    command.add_option("-D,--define", arguments.defines, "Override a #define constant: NAME=VALUE (repeatable)");
    command
        .add_option_function<std::string>(
            "--dialect", [&arguments](const std::string& name) { arguments.dialect = lsys::dialectFromName(name); },
            "Input notation: " + lsys::knownDialects() +
                " (default: the file's 'dialect:' line, else cpfg for a .l file, else native)")
        ->check([](const std::string& name) {
            return lsys::dialectFromName(name)
                       ? std::string()
                       : "unknown dialect '" + name + "' (expected " + lsys::knownDialects() + ")";
        });
}

void addDerivationOptions(CLI::App& command, DerivationArguments& arguments) {
    addPlantFileOptions(command, arguments);
    command.add_option("-n,--steps", arguments.steps, "Derivation steps (default: the file's 'derivation length:')")
        ->check(CLI::Range(0, lsys::kMaxDerivationLength));
    command.add_option("--seed", arguments.seed, "Random seed (default: the file's 'seed:')");
    addMemoryBudgetOption(command, arguments.memory);
}

std::optional<lsys::Grammar> loadGrammar(const DerivationArguments& arguments) {
    lsys::ParseOptions options;
    options.file = arguments.file;
    if (!parseDefines(arguments.defines, options.defines)) return std::nullopt;
    lsys::vlab::PlantFile plant = lsys::vlab::loadPlant(arguments.file, arguments.dialect, options);
    lsys::ParseResult& result = plant.parsed;
    std::cerr << lsys::formatDiagnostics(result.warnings, plant.source);
    if (!result.ok()) {
        std::cerr << lsys::formatDiagnostics(result.diagnostics, plant.source);
        std::cerr << result.diagnostics.size() << (result.diagnostics.size() == 1 ? " error\n" : " errors\n");
        return std::nullopt;
    }
    return std::move(result.grammar);
}

int failed(const DerivationArguments& arguments, const std::exception& error) {
    std::cerr << arguments.file << ": error: " << error.what();
    if (dynamic_cast<const lsys::ModuleBudgetError*>(&error))
        std::cerr << " (--max-modules sets the budget; -n derives fewer steps)";
    std::cerr << '\n';
    return kBadInput;
}

std::function<void(int, int, size_t)> derivationProgress() {
    using Clock = std::chrono::steady_clock;
    constexpr auto kInterval = std::chrono::seconds(5);
    const Clock::time_point start = Clock::now();
    auto last = std::make_shared<Clock::time_point>(start);
    return [start, last, kInterval](int step, int steps, size_t modules) {
        const Clock::time_point now = Clock::now();
        if (now - *last < kInterval || step == steps) return;
        *last = now;
        const double perStep = std::chrono::duration<double>(now - start).count() / step;
        const auto left = static_cast<long long>(perStep * (steps - step));
        const std::string eta = left >= 3600
                                    ? std::to_string(left / 3600) + " h " + std::to_string(left % 3600 / 60) + " min"
                                : left >= 60 ? std::to_string(left / 60) + " min"
                                             : std::to_string(left) + " s";
        std::cerr << "lsys: step " << step << " of " << steps << ", " << modules << " modules, about " << eta
                  << " left\n";
    };
}

lsys::DeriveOptions deriveOptions(const DerivationArguments& arguments) {
    lsys::DeriveOptions options;
    options.onStep = derivationProgress();
    options.steps = arguments.steps;
    options.seed = arguments.seed;
    options.maxModules = arguments.maxModules;
    options.memory = arguments.memory;
    return options;
}

lsys::BGrammarOptions bgrammarOptions(const DerivationArguments& arguments) {
    lsys::BGrammarOptions options;
    options.onStep = derivationProgress();
    options.steps = arguments.steps;
    options.seed = arguments.seed;
    options.interpreted = true; // the word the turtle reads
    options.maxModules = arguments.maxModules;
    options.memory = arguments.memory;
    return options;
}

} // namespace tools
