#include "output_check.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

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

std::string outputsProblem(const PlantfieldOptions& o) {
    const std::filesystem::path input = o.plantPath.empty() ? o.scenePath : o.plantPath;
    if (std::string problem = flaggedOutputsProblem({{"--capture", &o.capturePath},
                                                     {"--video", &o.videoPath},
                                                     {"--export", &o.exportPath},
                                                     {"--export-placements", &o.placementsPath}},
                                                    input);
        !problem.empty())
        return problem;
    // Only frames already there can be an input; the folder is created if missing.
    std::error_code error;
    if (o.outDir.empty() || !std::filesystem::is_directory(o.outDir, error)) return {};
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
