// --plant FILE: one plant previewed on flat ground, framed by an orbit
// camera (docs/PLANT_PREVIEW.md). The scene is built in memory: one
// species of the file (or vlab object folder), one plant at the origin in its
// own units, the default sun and sky, no wind unless --wind.
#pragma once

#include "options.h"

#include "engine/scene/camera.h"
#include "engine/scene/field_content.h"

#include <glm/glm.hpp>

namespace pf {

// The camera circles `centre` at `distance`, `elevationDegrees` above it.
struct PreviewOrbit {
    glm::vec3 centre{0.0f};
    float distance = 1.0f;
    float elevationDegrees = 20.0f;
    float azimuthDegrees = 0.0f;   // from the south (+z) toward the east (+x)
    float degreesPerSecond = 0.0f; // --orbit-speed
    float fovYDegrees = 45.0f;
};

// The one-species scene of --plant, before its plant is known: a small flat
// ground that framePreview sizes.
Scene previewScene(const PlantfieldOptions& o);

// Frames the built plant: the orbit from its bounding sphere (it fills about
// 80 % of the frame's height), and the ground and fog scaled with the
// orbit's distance, so the preview looks the same whatever the plant's units.
PreviewOrbit framePreview(FieldContent& content, const PlantfieldOptions& o);

// The orbit's camera at scene time t.
Camera orbitCamera(const PreviewOrbit& orbit, double t);

} // namespace pf
