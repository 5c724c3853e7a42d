// The built-in scene plantfield renders when no scene file is given.
#pragma once

#include "engine/camera.h"
#include "engine/scene_renderer.h"

namespace pf {

struct DefaultScene {
    SceneGeometry geometry;
    Environment environment;
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};
};

DefaultScene buildDefaultScene();

// The camera slowly circles the plant; t = 0 is the reference view.
Camera defaultCameraAt(const DefaultScene& scene, double t);

} // namespace pf
