// A scene file with some of its values replaced, as plantfield's --seed,
// --wind and --joint-budget and the Python module's arguments replace them.
#pragma once

#include "engine/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace pf {

struct SceneOverrides {
    std::optional<uint32_t> seed;
    std::optional<float> windSpeed;            // m/s
    std::optional<float> windDirectionDegrees; // where it blows toward, clockwise from north (-z) toward +x
    std::optional<uint32_t> jointBudget;       // physics.joint_budget
};

void applySceneOverrides(Scene& scene, const SceneOverrides& overrides);

// loadScene (SceneError naming file:line:column) with `overrides` applied.
Scene loadScene(const std::filesystem::path& file, const SceneOverrides& overrides,
                const lsys::MemoryBudget& memory = {});

} // namespace pf
