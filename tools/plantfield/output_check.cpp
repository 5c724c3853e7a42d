#include "output_check.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

#include <unistd.h>

#include "engine/scene/scene.h"
#include "lsystem/common/output_file.h"

namespace pf {

std::string framePath(const std::string& dir, uint32_t index) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04u.png", index);
    return (std::filesystem::path(dir) / name).string();
}

FrameSpan writtenFrames(const PlantfieldOptions& o) {
    if (o.frameRange) return {o.frameRange->first, o.frameRange->last + 1};
    return {0, std::max(o.frames, 1u)};
}

std::string folderProblem(const std::filesystem::path& folder) {
    // The folder, or the nearest of its parents that exists: create_directories makes the rest.
    std::filesystem::path existing = folder;
    std::error_code error;
    while (!std::filesystem::exists(std::filesystem::symlink_status(existing, error)) && existing.has_relative_path() &&
           existing.has_parent_path() && existing.parent_path() != existing)
        existing = existing.parent_path();
    if (existing.empty()) existing = ".";
    if (!std::filesystem::exists(existing, error)) return {};
    if (!std::filesystem::is_directory(existing, error))
        return "'" + existing.string() + "' is " + (existing == folder ? "" : "in the way: ") + "not a folder";
    if (access(existing.c_str(), W_OK) != 0) return "folder '" + existing.string() + "' is not writable";
    return {};
}

std::string outputsProblem(const PlantfieldOptions& o) {
    const std::filesystem::path input = o.plantPath.empty() ? o.scenePath : o.plantPath;
    if (std::string problem = flaggedOutputsProblem({{"--capture", &o.capturePath},
                                                     {"--video", &o.videoPath},
                                                     {"--export", &o.exportPath},
                                                     {"--export-placements", &o.placementsPath}},
                                                    input);
        !problem.empty())
        return problem;
    if (o.outDir.empty()) return {};
    if (std::string problem = folderProblem(o.outDir); !problem.empty()) return "cannot write --out-dir: " + problem;
    // Only frames already there can be an input; the folder is created if missing.
    std::error_code error;
    if (!std::filesystem::is_directory(o.outDir, error)) return {};
    const FrameSpan frames = writtenFrames(o);
    for (uint32_t i = frames.first; i < frames.end; ++i) {
        const std::string frame = framePath(o.outDir, i);
        if (!std::filesystem::exists(std::filesystem::symlink_status(frame, error))) continue;
        if (const std::string problem = lsys::outputPathProblem(frame, {&input, 1}); !problem.empty())
            return "cannot write --out-dir frame: " + problem;
    }
    return {};
}

void checkOutputsAfterLoad(const PlantfieldOptions& o) {
    if (const std::string problem = outputsProblem(o); !problem.empty()) throw SceneError(problem);
}

} // namespace pf
