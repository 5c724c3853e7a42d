#include "fuzz_targets.h"
#include "input_file.h"

#include "engine/scene/field_content.h"
#include "engine/scene/scene.h"

namespace pf::fuzz {

void runSceneInput(const uint8_t* data, size_t size) {
    try {
        const Scene scene = loadScene(writeInputFile(data, size, "scenes/input.json"));
        (void)placementRules(scene);
    } catch (const SceneError&) {
        // A clear error naming file, line and column is the right outcome.
    }
}

} // namespace pf::fuzz
