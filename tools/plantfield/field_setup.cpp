#include "field_setup.h"
#include "output_check.h"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <unistd.h>

namespace pf {
namespace {

// While a field is built, a line every 10 s on stderr saying what it is doing
// and for how long ("plantfield: placing plants, 60 s so far"): 16 million
// plants take minutes to place, and a log that stays silent that long reads as
// a hang. On a terminal the progress line in place says it instead.
class BuildHeartbeat {
public:
    explicit BuildHeartbeat(std::string stage) : stage_(std::move(stage)) {
        thread_ = std::thread([this] { beat(); });
    }
    BuildHeartbeat(const BuildHeartbeat&) = delete;
    BuildHeartbeat& operator=(const BuildHeartbeat&) = delete;
    ~BuildHeartbeat() {
        {
            const std::lock_guard lock(mutex_);
            done_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    void setStage(std::string stage) {
        const std::lock_guard lock(mutex_);
        stage_ = std::move(stage);
    }

private:
    void beat() {
        constexpr auto kInterval = std::chrono::seconds(10);
        const auto start = std::chrono::steady_clock::now();
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, kInterval, [this] { return done_; })) {
            const auto seconds =
                std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count();
            std::fprintf(stderr, "plantfield: %s, %lld s so far\n", stage_.c_str(), static_cast<long long>(seconds));
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;
    std::string stage_;
    bool done_ = false;
    std::thread thread_;
};

} // namespace

GpuOptions gpuOptions(const PlantfieldOptions& o) {
    GpuOptions g;
    g.validation = o.validation;
    g.deviceName = o.deviceName;
    g.hostMemoryLimit = o.memory.limitBytes;
    return g;
}

const std::string& inputName(const PlantfieldOptions& o) { return o.plantPath.empty() ? o.scenePath : o.plantPath; }

Scene loadSceneOf(const PlantfieldOptions& o) {
    if (!o.plantPath.empty()) return previewScene(o);
    return loadScene(o.scenePath, SceneOverrides{o.seed, o.windSpeed, o.windDirectionDegrees, o.jointBudget}, o.memory);
}

FieldContent loadFieldContent(const PlantfieldOptions& o, std::optional<PreviewOrbit>* orbit, ModelAssets assets) {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = loadSceneOf(o);
    std::optional<PlantCount> count;
    if (o.instances)
        count = PlantCount{size_t(*o.instances), o.densify ? CountMode::Densify : CountMode::NaturalDensity};
    // Progress in place on a terminal; a log gets a line every 10 s while the
    // build lasts (BuildHeartbeat), then the summary line below.
    const bool terminal = isatty(fileno(stderr));
    // buildFieldContent places the plants before it reports the models.
    if (terminal) std::fprintf(stderr, "\rplantfield: placing plants\x1b[K");
    std::optional<BuildHeartbeat> heartbeat;
    if (!terminal) heartbeat.emplace("placing plants");
    FieldContent content = buildFieldContent(
        scene, count,
        [&](size_t done, size_t all, const std::string& name) {
            if (heartbeat) heartbeat->setStage("plant models " + std::to_string(done) + "/" + std::to_string(all));
            if (!terminal) return;
            std::fprintf(stderr, "\rplantfield: plant models %zu/%zu (%s)\x1b[K", done, all, name.c_str());
            if (done == all) std::fprintf(stderr, "\r\x1b[K");
        },
        o.memory, assets);
    heartbeat.reset();
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
