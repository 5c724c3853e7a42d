// --plot: a PNG drawn by gnuplot of the sweep: milliseconds per pass against
// plants on log-log axes, and below it the cost per thousand plants.
#pragma once

#include "sweep.h"

namespace pf {

// Writes o.plotPath through a temporary file. Throws with gnuplot's own
// message when it fails or cannot be started.
void drawPlot(const PlantbenchOptions& o, const SweepResult& result);

} // namespace pf
