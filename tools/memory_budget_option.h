// --memory-budget SIZE, the same on lsys, plantfield and plantbench
// (lsystem/common/memory_budget.h): what every stage may allocate, by default 3/4
// of the memory this process may use (lsystem/common/machine_memory.h).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "lsystem/common/memory_budget.h"

namespace tools {

inline void addMemoryBudgetOption(CLI::App& app, lsys::MemoryBudget& budget) {
    budget = lsys::machineMemoryBudget();
    app.add_option_function<std::string>(
           "--memory-budget", [&budget](const std::string& text) { budget.limitBytes = *lsys::parseByteSize(text); },
           "Memory every stage may allocate (derivation, turtle, b-grammar, instance graph, export, terrain,\n"
           "plants, GPU uploads), e.g. 512M, 4G or bytes; past it a stage stops with an error naming it\n"
           "(default: 3/4 of what this process may use: available memory, cgroup limit or ulimit,\n"
           "the smallest; now " +
               lsys::formatBytes(budget.limitBytes) + ")")
        ->type_name("SIZE")
        ->check([](const std::string& text) -> std::string {
            return lsys::parseByteSize(text)
                       ? std::string()
                       : "'" + text + "' is not a size: expected bytes or a number with K, M, G or T, e.g. 4G";
        });
}

} // namespace tools
