// What every plantfield mode does first: read the scene, apply --seed and
// --instances, build the field on the CPU (with progress on stderr), and
// open the GPU renderer.
#pragma once

#include "options.h"

#include "engine/field/field_renderer.h"
#include "engine/vk/device.h"

#include <memory>

namespace pf {

GpuOptions gpuOptions(const PlantfieldOptions& o);

// The scene file with --seed and --wind applied. Throws SceneError
// (file:line:column) with a clear message.
Scene loadSceneOf(const PlantfieldOptions& o);

// Throws SceneError (file:line:column) or runtime_error with a clear message.
FieldContent loadFieldContent(const PlantfieldOptions& o);

FieldRenderSettings renderSettings(const PlantfieldOptions& o);

// The view at scene time t along the scene's camera path.
FieldView pathView(const PlantfieldOptions& o, const Scene& scene, double t, double dt, bool firstFrame);

} // namespace pf
