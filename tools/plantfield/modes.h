// plantfield's two ways to render: headless to PNG (and JSON statistics),
// and the real-time window.
#pragma once

#include "options.h"

namespace pf {

int runHeadless(const PlantfieldOptions& o);
int runWindow(const PlantfieldOptions& o);
// --physics-check: GPU physics against the CPU reference (tools/plantfield/physics_check.cpp).
int runPhysicsCheck(const PlantfieldOptions& o);

} // namespace pf
