// What a sweep reports: the summary table on stdout, --json and --csv.
// docs/PLANTBENCH.md describes every field and column.
#pragma once

#include "sweep.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>

namespace pf {

// naive frame ms median / GPU-driven frame ms median; nullopt without naive.
std::optional<double> naiveRatio(const CountResult& r);

void printSummaryTable(std::ostream& out, const PlantbenchOptions& o, const SweepResult& result);
nlohmann::json sweepJson(const PlantbenchOptions& o, const SweepResult& result);
// A header row, then one row per count; empty cells where a value is absent.
// With --path the row is the worst time's, followed by every time's frame ms.
std::string sweepCsv(const PlantbenchOptions& o, const SweepResult& result);

// Writes `text` to a temporary file next to `path` and renames it into
// place, so a failure never leaves a half-written file. Throws with the path.
void writeTextFile(const std::string& path, const std::string& text);

} // namespace pf
