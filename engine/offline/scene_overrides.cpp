#include "scene_overrides.h"

namespace pf {

void applySceneOverrides(Scene& scene, const SceneOverrides& overrides) {
    if (overrides.seed) scene.seed = *overrides.seed;
    if (overrides.windSpeed) scene.wind.speed = *overrides.windSpeed;
    if (overrides.windDirectionDegrees) scene.wind.directionDegrees = *overrides.windDirectionDegrees;
    if (overrides.jointBudget) scene.physics.jointBudget = *overrides.jointBudget;
}

Scene loadScene(const std::filesystem::path& file, const SceneOverrides& overrides, const lsys::MemoryBudget& memory) {
    Scene scene = loadScene(file, memory);
    applySceneOverrides(scene, overrides);
    return scene;
}

} // namespace pf
