#include "field_setup.h"
#include "output_check.h"

#include <chrono>
#include <cstdio>

#include <unistd.h>

namespace pf {

GpuOptions gpuOptions(const PlantfieldOptions& o) {
    GpuOptions g;
    g.validation = o.validation;
    g.deviceName = o.deviceName;
    return g;
}

const std::string& inputName(const PlantfieldOptions& o) { return o.plantPath.empty() ? o.scenePath : o.plantPath; }

Scene loadSceneOf(const PlantfieldOptions& o) {
    if (!o.plantPath.empty()) return previewScene(o);
    return loadScene(o.scenePath, SceneOverrides{o.seed, o.windSpeed, o.windDirectionDegrees, o.jointBudget});
}

FieldContent loadFieldContent(const PlantfieldOptions& o, std::optional<PreviewOrbit>* orbit, ModelAssets assets) {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = loadSceneOf(o);
    std::optional<PlantCount> count;
    if (o.instances)
        count = PlantCount{size_t(*o.instances), o.densify ? CountMode::Densify : CountMode::NaturalDensity};
    // Progress on a terminal only; logs get the summary line below.
    const bool terminal = isatty(fileno(stderr));
    // buildFieldContent places the plants before it reports the models.
    if (terminal) std::fprintf(stderr, "\rplantfield: placing plants\x1b[K");
    FieldContent content = buildFieldContent(
        scene, count,
        [&](size_t done, size_t all, const std::string& name) {
            if (!terminal) return;
            std::fprintf(stderr, "\rplantfield: plant models %zu/%zu (%s)\x1b[K", done, all, name.c_str());
            if (done == all) std::fprintf(stderr, "\r\x1b[K");
        },
        o.memory, assets);
    checkOutputsAfterLoad(o); // the scene's plants, includes and textures are known now
    if (!o.plantPath.empty()) {
        const PreviewOrbit framed = framePreview(content, o);
        if (orbit) *orbit = framed;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "plantfield: %s: %zu plants of %zu species on %.0f m x %.0f m, %zu models, built in %.1f s\n",
                 inputName(o).c_str(), content.plants.size(), content.scene.species.size(), content.scene.terrain.size,
                 content.scene.terrain.size, content.models.models.size(), seconds);
    if (!content.note.empty()) std::fprintf(stderr, "plantfield: note: %s\n", content.note.c_str());
    std::fputs(content.models.warnings.c_str(), stderr);
    return content;
}

FieldRenderSettings renderSettings(const PlantfieldOptions& o) {
    FieldRenderSettings s;
    s.antialiasing = o.antialiasing;
    s.shadows = o.shadows;
    s.occlusionCulling = o.occlusionCulling;
    s.shadowCache.reuse = o.shadowCache;
    // The far canopy's distances are metres: a --plant of many units would be
    // drawn as canopy from its orbit, so the preview's one plant skips it.
    s.clusters.enabled = o.clusters && o.plantPath.empty();
    s.memory = o.memory;
    return s;
}

FieldView pathView(const PlantfieldOptions& o, const Scene& scene, double t, double dt, bool firstFrame,
                   const std::optional<PreviewOrbit>& orbit) {
    return frameView(orbit ? orbitCamera(*orbit, t) : cameraAt(scene.camera, t), t, dt, firstFrame, o.forcedLod);
}

OfflineSettings offlineSettings(const PlantfieldOptions& o, const std::optional<PreviewOrbit>& orbit) {
    OfflineSettings s;
    s.size = {o.size.width, o.size.height};
    s.render = renderSettings(o);
    s.gpu = gpuOptions(o);
    s.forcedLod = o.forcedLod;
    if (orbit) s.camera = [orbit = *orbit](double t) { return orbitCamera(orbit, t); };
    s.start = o.time;
    s.fps = o.fps;
    return s;
}

} // namespace pf
