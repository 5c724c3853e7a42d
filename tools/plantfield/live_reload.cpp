#include "live_reload.h"

#include "lsystem/common/file_reader.h"

#include <algorithm>
#include <cstdio>
#include <new>
#include <typeinfo>

namespace pf {

FieldBuild buildField(const PlantfieldOptions& o) {
    FieldBuild build;
    {
        const lsys::ReadFileLog read;
        try {
            std::optional<PreviewOrbit> orbit;
            build.content = loadFieldContent(o, &orbit);
            build.orbit = orbit;
        } catch (const std::exception& e) { // SceneError, DerivationError, bad_alloc and the rest
            build.failure = std::current_exception();
            build.error = dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory" : e.what();
        }
        build.files = read.paths();
    }
    const std::filesystem::path input = std::filesystem::path(inputName(o)).lexically_normal();
    if (std::find(build.files.begin(), build.files.end(), input) == build.files.end()) build.files.push_back(input);
    return build;
}

FieldReloader watchBuild(const FieldBuild& build) {
    FieldReloader reloader;
    reloader.watch = watchFiles(build.files);
    return reloader;
}

std::optional<FieldBuild> pollReload(FieldReloader& reloader, const PlantfieldOptions& o, WatchClock::time_point now) {
    if (reloader.building.valid()) {
        if (reloader.building.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        FieldBuild build = reloader.building.get();
        // The rebuild read them on its own thread: noted on this one too, the
        // run's, so the window's outputs (--capture) never replace them.
        for (const std::filesystem::path& file : build.files) lsys::noteFileRead(file);
        rewatchFiles(reloader.watch, build.files);
        return build;
    }
    if (now < reloader.nextPoll) return std::nullopt;
    reloader.nextPoll = now + kWatchPollInterval;
    const std::vector<std::filesystem::path> changed = pollChanges(reloader.watch, now);
    if (changed.empty()) return std::nullopt;
    std::fprintf(stderr, "plantfield: %s%s changed, rebuilding\n", changed.front().string().c_str(),
                 changed.size() > 1 ? (" and " + std::to_string(changed.size() - 1) + " more").c_str() : "");
    reloader.building = std::async(std::launch::async, buildField, std::cref(o));
    return std::nullopt;
}

} // namespace pf
