// What a loaded Scene means at run time: the camera along its path, the seeds
// the file leaves out, and the renderer's environment settings.
#include "engine/scene/scene.h"

#include "lsystem/components/component_graph.h"
#include "lsystem/ramification/ramification_file.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// SplitMix64's finaliser: nearby (seed, stream) pairs give unrelated seeds.
uint32_t mixSeed(uint32_t seed, uint32_t stream) {
    uint64_t x = (uint64_t(seed) << 32 | stream) + 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return uint32_t(x ^ (x >> 31));
}

// Streams: 0 terrain, then two per species (its L-system, its placement).
uint32_t speciesStream(size_t species, uint32_t which) { return 1 + 2 * uint32_t(species) + which; }

// Cubic Hermite on one span of length h, at u in [0, 1].
template <typename T>
T hermite(const T& p0, const T& m0, const T& p1, const T& m1, float h, float u) {
    const float u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * h * m1;
}

// Catmull-Rom tangent at key i from its neighbours' values and times, one-sided
// at the ends, so the camera's speed follows the keyframe timing.
template <typename T, typename Value>
T tangent(const std::vector<CameraKeyframe>& keys, size_t i, Value value) {
    const size_t before = i > 0 ? i - 1 : i;
    const size_t after = std::min(i + 1, keys.size() - 1);
    return (value(keys[after]) - value(keys[before])) / float(keys[after].time - keys[before].time);
}

template <typename T, typename Value>
T splineAt(const std::vector<CameraKeyframe>& keys, size_t i, float u, Value value) {
    const float h = float(keys[i + 1].time - keys[i].time);
    return hermite<T>(value(keys[i]), tangent<T>(keys, i, value), value(keys[i + 1]), tangent<T>(keys, i + 1, value), h,
                      u);
}

// Without keyframes: circle the origin once every two minutes, 60 m out and 20 m up.
constexpr double kDefaultOrbitSeconds = 120.0;
Camera defaultOrbit(double t) {
    constexpr float kRadius = 60.0f, kHeight = 20.0f,
                    kRadiansPerSecond = 2.0f * 3.14159265f / float(kDefaultOrbitSeconds);
    const float angle = glm::radians(30.0f) + float(t) * kRadiansPerSecond;
    Camera camera;
    camera.position = glm::vec3(std::sin(angle) * kRadius, kHeight, std::cos(angle) * kRadius);
    camera.target = glm::vec3(0.0f, 2.0f, 0.0f);
    return camera;
}

} // namespace

Camera cameraAt(const CameraPath& path, double t) {
    // NaN fails every comparison below, so it would pick no span: it is the start.
    if (std::isnan(t)) t = path.keyframes.empty() ? 0.0 : path.keyframes.front().time;
    const std::vector<CameraKeyframe>& keys = path.keyframes;
    Camera camera = keys.empty() ? defaultOrbit(t) : Camera{};
    camera.fovYDegrees = path.fovYDegrees;
    camera.nearPlane = path.nearPlane;
    camera.farPlane = path.farPlane;
    if (keys.empty()) return camera;

    const auto position = [](const CameraKeyframe& k) { return k.position; };
    const auto target = [](const CameraKeyframe& k) { return k.target; };
    const auto fov = [&](const CameraKeyframe& k) { return k.fovYDegrees.value_or(path.fovYDegrees); };
    if (keys.size() == 1 || t <= keys.front().time || t >= keys.back().time) {
        const CameraKeyframe& end = t <= keys.front().time ? keys.front() : keys.back();
        camera.position = end.position;
        camera.target = end.target;
        camera.fovYDegrees = fov(end);
        return camera;
    }
    // The span holding t: the last key at or before it.
    const auto next =
        std::upper_bound(keys.begin(), keys.end(), t, [](double v, const CameraKeyframe& k) { return v < k.time; });
    const size_t i = size_t(next - keys.begin()) - 1;
    const float u = float((t - keys[i].time) / (keys[i + 1].time - keys[i].time));
    camera.position = splineAt<glm::vec3>(keys, i, u, position);
    camera.target = splineAt<glm::vec3>(keys, i, u, target);
    // The spline may overshoot between keys; a field of view must stay valid.
    camera.fovYDegrees = std::clamp(splineAt<float>(keys, i, u, fov), 1.0f, 179.0f);
    return camera;
}

std::vector<double> timesAlongPath(const CameraPath& path, uint32_t count) {
    std::vector<double> times;
    if (path.keyframes.empty()) {
        // The orbit comes back to its start, so the last step stops short of a full turn.
        for (uint32_t i = 0; i < count; ++i) times.push_back(kDefaultOrbitSeconds * i / count);
        return times;
    }
    const double first = path.keyframes.front().time, last = path.keyframes.back().time;
    for (uint32_t i = 0; i < count; ++i) times.push_back(count == 1 ? first : first + (last - first) * i / (count - 1));
    return times;
}

uint32_t terrainSeed(const Scene& scene) {
    const auto* noise = std::get_if<NoiseHeightfield>(&scene.terrain.heightfield);
    return noise && noise->seed ? *noise->seed : mixSeed(scene.seed, 0);
}

uint32_t speciesSeed(const Scene& scene, size_t species) {
    return scene.species[species].seed.value_or(mixSeed(scene.seed, speciesStream(species, 0)));
}

glm::vec3 windHeading(const Wind& wind) {
    const float direction = glm::radians(wind.directionDegrees); // clockwise from -z (north) toward +x
    return glm::vec3(std::sin(direction), 0.0f, -std::cos(direction));
}

glm::vec3 meanWindVelocity(const Wind& wind) { return wind.speed * windHeading(wind); }

bool isPlantModelFile(const std::filesystem::path& file) {
    return lsys::isRamificationFile(file) || lsys::components::isComponentFile(file);
}

uint32_t placementSeed(const Scene& scene, size_t species) {
    return scene.species[species].placement.seed.value_or(mixSeed(scene.seed, speciesStream(species, 1)));
}

Environment environmentOf(const Scene& scene) {
    Environment env;
    env.sunElevationDegrees = scene.sun.elevationDegrees;
    env.sunAzimuthDegrees = scene.sun.azimuthDegrees;
    env.sunRadiance = scene.sun.color * scene.sun.intensity;
    env.skyZenith = scene.sky.zenith;
    env.skyHorizon = scene.sky.horizon;
    env.groundAlbedo = scene.terrain.albedo;
    env.fogDensity = scene.fog.density;
    env.groundHalfSize = 0.5f * scene.terrain.size;
    return env;
}

} // namespace pf
