// The output rule (lsystem/common/output_file.h) over plantfield's outputs:
// --capture, --video, --export, --export-placements and the frames a
// --frames sequence writes into --out-dir are refused when they cannot be
// written or are a file the run reads. Checked while parsing,
// against the scene or --plant named on the command line, and again once the
// field is loaded, against every file the load read (main keeps a
// lsys::ReadFileLog open for the whole run): the plants, includes, view and
// colour-map files, surfaces and textures the scene named.
#pragma once

#include "options.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace pf {

// The file of frame `index` of a --frames sequence: DIR/frame_0000.png, ...
std::string framePath(const std::string& dir, uint32_t index);

// The frames a --frames sequence writes: [first, end), --frame-range's or all.
struct FrameSpan {
    uint32_t first = 0, end = 0;
};
FrameSpan writtenFrames(const PlantfieldOptions& o);

// Why files cannot be written into `folder`, made with its missing parents
// (create_directories), before any work: the folder or the nearest parent
// that exists is not a folder ("'s.json' is not a folder") or not writable.
// Empty when they can.
std::string folderProblem(const std::filesystem::path& folder);

// "cannot write --capture file: REASON" for the first output refused; empty
// when every output may be written.
std::string outputsProblem(const PlantfieldOptions& o);

// Throws SceneError with outputsProblem's message (exit 2): after the load,
// before the frames or exports.
void checkOutputsAfterLoad(const PlantfieldOptions& o);

} // namespace pf
