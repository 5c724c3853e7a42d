#include "lsystem/common/memory_budget.h"

#include "lsystem/common/machine_memory.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace lsys {

MemoryBudget machineMemoryBudget() {
    return {budgetBytesFrom(machineMemoryHeadroom()).value_or(kFallbackMemoryBudget)};
}

uint64_t bytesTimes(uint64_t count, uint64_t bytesEach) {
    uint64_t product;
    return __builtin_mul_overflow(count, bytesEach, &product) ? UINT64_MAX : product;
}

uint64_t bytesPlus(uint64_t a, uint64_t b) {
    uint64_t sum;
    return __builtin_add_overflow(a, b, &sum) ? UINT64_MAX : sum;
}

std::string formatBytes(uint64_t bytes) {
    if (bytes < 1024) return std::to_string(bytes) + " B";
    static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = double(bytes) / 1024.0;
    size_t unit = 0;
    for (; value >= 1023.95 && unit + 1 < std::size(kUnits); value /= 1024.0) ++unit;
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
    return text;
}

void need(const MemoryBudget& budget, std::string_view stage, uint64_t bytes) {
    if (bytes <= budget.limitBytes) return;
    std::string needed = formatBytes(bytes), limit = formatBytes(budget.limitBytes);
    if (needed == limit) { // just past it: the rounded sizes would read alike
        needed = std::to_string(bytes) + " B";
        limit = std::to_string(budget.limitBytes) + " B";
    }
    if (bytes == UINT64_MAX) needed = "more than " + needed; // saturated
    throw MemoryBudgetError("memory budget: " + std::string(stage) + " needs " + needed + ", the limit is " + limit +
                            " (set with --memory-budget)");
}

std::optional<uint64_t> parseByteSize(std::string_view text) {
    double number = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error != std::errc() || end == text.data() || !std::isfinite(number) || number <= 0.0) return std::nullopt;
    std::string unit(end, text.data() + text.size());
    for (char& c : unit) c = char(std::tolower(static_cast<unsigned char>(c)));
    double scale = 1.0;
    if (!unit.empty() && unit != "b") {
        static constexpr std::string_view kPrefixes = "kmgt";
        const size_t power = kPrefixes.find(unit.front());
        const std::string_view suffix = std::string_view(unit).substr(1);
        if (power == std::string_view::npos || !(suffix.empty() || suffix == "b" || suffix == "ib"))
            return std::nullopt;
        scale = std::ldexp(1.0, 10 * int(power + 1));
    }
    const double bytes = std::floor(number * scale);
    if (bytes < 1.0 || bytes >= 18446744073709551616.0) return std::nullopt; // 2^64
    return uint64_t(bytes);
}

} // namespace lsys
