// --watch with --window (docs/PLANT_PREVIEW.md "The edit loop"): the field is
// built again, off the render thread, whenever a file it was built from
// changes on disk, and handed to the window between frames.
#pragma once

#include "field_setup.h"

#include "engine/scene/file_watch.h"

#include <exception>
#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <vector>

namespace pf {

// How often the watched files are stamped (engine/scene/file_watch.h): a
// save is seen within about this plus the watch's settle time.
inline constexpr std::chrono::milliseconds kWatchPollInterval{250};

// One build of the field, and the files it read.
struct FieldBuild {
    std::optional<FieldContent> content; // empty when the build failed
    std::optional<PreviewOrbit> orbit;   // with --plant: the camera's orbit around the new plant
    std::string error;                   // why it failed, as the one-shot run reports it ("plant.lsys:3:1: …")
    std::exception_ptr failure;          // what loadFieldContent threw, for the first build to end the run with
    // Every file the build read or tried to read (lsys::ReadFileLog), and the
    // input itself: a --plant folder, whose time changes when a file
    // appears in it (a view file added beside the L-system).
    std::vector<std::filesystem::path> files;
};

// loadFieldContent(o) with what it throws caught into `error`.
FieldBuild buildField(const PlantfieldOptions& o);

struct FieldReloader {
    FileWatch watch;
    std::future<FieldBuild> building; // valid while a rebuild runs
    WatchClock::time_point nextPoll{};
};

// Watches the files `build` read.
FieldReloader watchBuild(const FieldBuild& build);

// Call every frame: stamps the files every kWatchPollInterval and, on a
// settled change, starts a rebuild on a thread of its own (reported on
// stderr: "plantfield: FILE changed, rebuilding"). Returns a finished
// rebuild, once, and from then watches the files that one read. Options
// must outlive the reloader.
std::optional<FieldBuild> pollReload(FieldReloader& reloader, const PlantfieldOptions& o, WatchClock::time_point now);

} // namespace pf
