// The output rule (lsystem/common/output_file.h) over plantfield's outputs:
// --capture, --video, --export and --export-placements are refused when they
// cannot be written or are a file the run reads. Checked while parsing,
// against the scene or --plant named on the command line, and again once the
// field is loaded, against every file the load read (main keeps a
// lsys::ReadFileLog open for the whole run): the plants, includes, view and
// colour-map files, surfaces and textures the scene named.
#pragma once

#include "options.h"

#include <string>

namespace pf {

// "cannot write --capture file: REASON" for the first output refused; empty
// when every output may be written.
std::string outputsProblem(const PlantfieldOptions& o);

// Throws SceneError with outputsProblem's message (exit 2): after the load,
// before the frames or exports.
void checkOutputsAfterLoad(const PlantfieldOptions& o);

} // namespace pf
