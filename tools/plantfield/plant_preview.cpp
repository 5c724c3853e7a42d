#include "plant_preview.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

constexpr float kFillShare = 0.8f;      // of the frame's height the bounding sphere spans
constexpr float kGroundSpan = 40.0f;    // ground side in orbit distances
constexpr float kFogPerDistance = 0.1f; // optical depth of fog along one orbit distance

} // namespace

Scene previewScene(const PlantfieldOptions& o) {
    Scene scene;
    scene.file = o.plantPath;
    scene.description = "plant preview of " + o.plantPath;
    if (o.seed) scene.seed = *o.seed;
    // Flat, one quad: framePreview sizes it to the plant.
    scene.terrain.size = 1.0f;
    scene.terrain.resolution = 2;
    NoiseHeightfield flat;
    flat.amplitude = 0.0f;
    flat.octaves = 1;
    scene.terrain.heightfield = flat;
    scene.wind.speed = o.windSpeed.value_or(0.0f);
    scene.wind.gustStrength = scene.wind.speed > 0.0f ? scene.wind.gustStrength : 0.0f;
    scene.wind.turbulence = scene.wind.speed > 0.0f ? scene.wind.turbulence : 0.0f;
    if (o.windDirectionDegrees) scene.wind.directionDegrees = *o.windDirectionDegrees;
    if (o.jointBudget) scene.physics.jointBudget = *o.jointBudget;

    Species species;
    const std::filesystem::path path = std::filesystem::path(o.plantPath).lexically_normal();
    species.name = path.has_filename() ? path.stem().string() : path.parent_path().filename().string();
    if (species.name.empty()) species.name = "plant";
    if (isPlantModelFile(path)) {
        species.model = path; // takes no defines or steps
    } else {
        species.lsystem = path;
        species.defines = o.plantDefines;
        species.steps = o.plantSteps;
    }
    species.seed = o.seed;
    species.height = o.plantHeight;
    // Full detail at any size: the preview is of the plant, not of its LODs.
    species.lod.reducedBelowPixels = 0.0f;
    species.lod.impostorBelowPixels = 0.0f;
    species.lod.hiddenBelowPixels = 0.0f;
    species.placement.mode = PlacementMode::Explicit;
    species.placement.instances = {PlacedPlant{}};
    scene.species.push_back(std::move(species));
    return scene;
}

PreviewOrbit framePreview(FieldContent& content, const PlantfieldOptions& o) {
    PreviewOrbit orbit;
    orbit.azimuthDegrees = float(o.orbitDegrees);
    orbit.degreesPerSecond = float(o.orbitSpeed);
    orbit.fovYDegrees = content.scene.camera.fovYDegrees;
    glm::vec3 centre(0.0f, 0.5f, 0.0f);
    float radius = 0.5f; // a plant that draws nothing: a metre-high space above the origin
    if (!content.models.models.empty()) {
        const glm::vec4 sphere = content.models.models[0].gpu.sphere;
        const float scale = content.plants.empty() ? 1.0f : content.plants[0].scale;
        if (std::isfinite(sphere.w) && sphere.w > 0.0f && std::isfinite(sphere.x + sphere.y + sphere.z)) {
            centre = glm::vec3(sphere) * scale;
            radius = sphere.w * scale;
        }
    }
    if (!content.plants.empty()) centre.y += content.plants[0].position.y;
    orbit.centre = centre;
    // The narrower of the two fields of view: a portrait frame fits the plant's width.
    const float halfFovY = 0.5f * glm::radians(orbit.fovYDegrees);
    const float aspect = float(o.size.width) / float(o.size.height);
    const float halfFov = std::min(halfFovY, std::atan(std::tan(halfFovY) * aspect));
    const float halfFill = kFillShare * halfFov;
    orbit.distance = radius / std::sin(halfFill);

    // Ground and fog in units of the orbit's distance.
    Scene& scene = content.scene;
    scene.terrain.size = kGroundSpan * orbit.distance;
    scene.terrain.resolution = 65;
    content.terrain = terrainOf(scene, o.memory);
    scene.fog.density = kFogPerDistance / orbit.distance;
    return orbit;
}

Camera orbitCamera(const PreviewOrbit& orbit, double t) {
    const double azimuth = glm::radians(double(orbit.azimuthDegrees) + double(orbit.degreesPerSecond) * t);
    const double elevation = glm::radians(double(orbit.elevationDegrees));
    const glm::vec3 offset(float(std::sin(azimuth) * std::cos(elevation)), float(std::sin(elevation)),
                           float(std::cos(azimuth) * std::cos(elevation)));
    Camera camera;
    camera.target = orbit.centre;
    camera.position = orbit.centre + orbit.distance * offset;
    camera.fovYDegrees = orbit.fovYDegrees;
    camera.nearPlane = 0.005f * orbit.distance;
    camera.farPlane = kGroundSpan * orbit.distance;
    return camera;
}

} // namespace pf
