// What every plantfield mode does first: read the scene, apply --seed and
// --instances, build the field on the CPU (with progress on stderr), and
// open the GPU renderer.
#pragma once

#include "options.h"
#include "plant_preview.h"

#include "engine/field/field_renderer.h"
#include "engine/offline/offline_renderer.h"
#include "engine/offline/scene_overrides.h"
#include "engine/vk/device.h"

#include <memory>

namespace pf {

GpuOptions gpuOptions(const PlantfieldOptions& o);

// What the tool renders, for messages: the scene file or the --plant.
const std::string& inputName(const PlantfieldOptions& o);

// The scene file with --seed and --wind applied (with --plant, previewScene). Throws SceneError
// (file:line:column) with a clear message.
Scene loadSceneOf(const PlantfieldOptions& o);

// Throws SceneError (file:line:column) or runtime_error with a clear message.
// With --plant, the ground is sized to the plant and `orbit` (when given) is
// set to the preview's camera orbit. `assets`: whether the models' plants are
// kept (buildFieldContent), as the glTF export needs.
FieldContent loadFieldContent(const PlantfieldOptions& o, std::optional<PreviewOrbit>* orbit = nullptr,
                              ModelAssets assets = ModelAssets::Drop);

FieldRenderSettings renderSettings(const PlantfieldOptions& o);

// The view at scene time t along the scene's camera path, or on the --plant
// preview's orbit when one is given.
FieldView pathView(const PlantfieldOptions& o, const Scene& scene, double t, double dt, bool firstFrame,
                   const std::optional<PreviewOrbit>& orbit = std::nullopt);

// What a headless run renders with: the size, renderSettings, gpuOptions, the
// --time and --fps of its frames, and the camera on the path or the orbit.
OfflineSettings offlineSettings(const PlantfieldOptions& o, const std::optional<PreviewOrbit>& orbit);

} // namespace pf
