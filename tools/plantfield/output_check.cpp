#include "output_check.h"

#include <filesystem>
#include <utility>

#include "engine/scene/scene.h"
#include "lsystem/common/output_file.h"

namespace pf {

std::string outputsProblem(const PlantfieldOptions& o) {
    const std::filesystem::path input = o.plantPath.empty() ? o.scenePath : o.plantPath;
    for (const auto& [flag, path] : {std::pair{"--capture", &o.capturePath},
                                     {"--video", &o.videoPath},
                                     {"--export", &o.exportPath},
                                     {"--export-placements", &o.placementsPath}}) {
        if (path->empty()) continue;
        if (const std::string problem = lsys::outputPathProblem(*path, {&input, 1}); !problem.empty())
            return std::string("cannot write ") + flag + " file: " + problem;
    }
    return {};
}

void checkOutputsAfterLoad(const PlantfieldOptions& o) {
    if (const std::string problem = outputsProblem(o); !problem.empty()) throw SceneError(problem);
}

} // namespace pf
