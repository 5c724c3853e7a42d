// A scene file (data/scenes/*.json, docs/SCENE_FORMAT.md) read into plain
// structs: terrain, species, placement, sun, sky, fog, wind, camera path and clouds.
// Units are metres, degrees and seconds; y is up. Loading touches no GPU.
#pragma once

#include "engine/scene/camera.h"
#include "engine/scene/cloud_spheres.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/landscape/terrain_bumps.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace pf {

// Every problem in a scene file: "file:line:column: /json/pointer message".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Fractal gradient noise (fBm): octave i has frequency frequency·lacunarityⁱ
// and amplitude amplitude·gainⁱ (engine/scene/terrain.h makeNoiseTerrain).
struct NoiseHeightfield {
    std::optional<uint32_t> seed; // empty: derived from the scene seed (terrainSeed)
    uint32_t octaves = 5;
    float amplitude = 16.0f;         // metres, of the first octave
    float frequency = 1.0f / 200.0f; // cycles per metre, of the first octave: hills about 200 m apart
    float lacunarity = 2.0f;
    float gain = 0.5f;
    bool operator==(const NoiseHeightfield&) const = default;
};

// A square greyscale PNG, one sample a pixel: grey g is g/255·heightScale.
struct ImageHeightfield {
    std::filesystem::path path; // resolved against the scene file's folder
    float heightScale = 20.0f;  // metres at white
    bool operator==(const ImageHeightfield&) const = default;
};

// L-system mountains (docs/TERRAIN_LSYSTEMS.md): the hills and valleys a
// turtle leaves, added to the noise or image heightfield (or to flat ground).
struct TerrainLsystem {
    std::filesystem::path path;                      // resolved against the scene file's folder
    glm::vec2 origin{0.0f};                          // x, z in metres where the turtle starts
    float headingDegrees = 0.0f;                     // its start heading, counter-clockwise from +x seen from above
    float scale = 10.0f;                             // metres per turtle unit
    float maxHeight = 200.0f;                        // metres the superimposed bumps may reach up or down
    std::optional<uint32_t> seed;                    // empty: the L-system file's own
    std::vector<lsys::landscape::TerrainBump> bumps; // derived when the scene is loaded
    bool operator==(const TerrainLsystem&) const = default;
};

// The most height samples a terrain side may have: 8193² floats are 256 MiB.
constexpr uint32_t kMaxTerrainResolution = 8193;

// A square centred on the origin.
struct Terrain {
    float size = 512.0f;       // side in metres
    uint32_t resolution = 257; // height samples along each side (an image gives its own)
    std::variant<NoiseHeightfield, ImageHeightfield> heightfield; // flat (no noise) when only an L-system is given
    glm::vec3 albedo{0.13f, 0.22f, 0.055f};
    std::optional<TerrainLsystem> lsystem; // its bumps are added to the heightfield
    bool operator==(const Terrain&) const = default;
};

// One plant given by hand instead of generated.
struct PlacedPlant {
    glm::vec2 position{0.0f};     // x, z in metres; the plant stands on the terrain
    float rotationDegrees = 0.0f; // about +y
    float scale = 1.0f;
    bool operator==(const PlacedPlant&) const = default;
};

// How many plants a species gets: one way per placement.
enum class PlacementMode {
    Density,  // densityPerHectare, which sets the Poisson-disk distance
    Distance, // Poisson-disk sampling at minDistance
    Count,    // exactly count plants
    Explicit, // exactly the listed instances
};

struct Placement {
    PlacementMode mode = PlacementMode::Density;
    float densityPerHectare = 50.0f;    // Density
    float minDistance = 1.0f;           // Distance: metres between plants of the species
    uint32_t count = 0;                 // Count
    std::vector<PlacedPlant> instances; // Explicit
    float clearance = 0.0f;             // metres kept free of other species' plants
    float maxSlopeDegrees = 90.0f;      // steeper ground gets no plant
    glm::vec2 heightRange{std::numeric_limits<float>::lowest(), std::numeric_limits<float>::max()}; // metres
    glm::vec2 scaleRange{1.0f, 1.0f}; // uniform random scale per plant
    std::optional<uint32_t> seed;     // empty: derived from the scene seed (placementSeed)
    bool operator==(const Placement&) const = default;
};

// Tankard 2001's billboards: one camera-facing quad, or two / three crossed quads.
enum class BillboardKind { Single, Double, Triple };

// Where the renderer switches level of detail, by projected height on screen.
struct LodHints {
    BillboardKind billboard = BillboardKind::Double;
    float reducedBelowPixels = 300.0f; // LOD0 → LOD1
    float impostorBelowPixels = 80.0f; // LOD1 → LOD2; never above reducedBelowPixels
    float hiddenBelowPixels = 0.0f;    // not drawn at all when smaller; never above impostorBelowPixels
    bool operator==(const LodHints&) const = default;
};

// Replaces the albedo of one entry of the turtle's palette (lsys::defaultPalette).
struct MaterialOverride {
    uint32_t index = 0;
    glm::vec3 albedo{0.5f};
    bool operator==(const MaterialOverride&) const = default;
};

struct Species {
    std::string name;
    // The plant: an L-system, or else a model file; exactly one is set. Both
    // are resolved against the scene file's folder and exist.
    std::filesystem::path lsystem;         // an L-system file or vlab object folder
    std::filesystem::path model;           // a .ram.json tree type or a .comp.json component plant
    std::map<std::string, double> defines; // L-system only: #define overrides, as `lsys -D NAME=VALUE`
    std::optional<uint32_t> steps;         // L-system only; empty: the file's derivation length
    uint32_t variants = 1;                 // distinct plants, made with seeds seed, seed+1, …
    std::optional<uint32_t> seed;          // empty: derived from the scene seed (speciesSeed)
    std::optional<float> height;           // metres the derived plant is scaled to; empty: its own units
    LodHints lod;
    std::vector<MaterialOverride> materials; // sorted by index, each index once
    Placement placement;
    bool operator==(const Species&) const = default;
};

struct Sun {
    float elevationDegrees = 38.0f;
    float azimuthDegrees = 140.0f; // clockwise from -z (north) toward +x
    glm::vec3 color{1.0f, 0.95f, 0.84f};
    float intensity = 1.9f;
    bool operator==(const Sun&) const = default;
};

struct Sky {
    glm::vec3 zenith{0.16f, 0.30f, 0.62f};
    glm::vec3 horizon{0.62f, 0.72f, 0.85f};
    bool operator==(const Sky&) const = default;
};

struct Fog {
    float density = 0.0025f; // extinction per metre
    bool operator==(const Fog&) const = default;
};

struct Wind {
    float speed = 3.0f;             // metres per second
    float directionDegrees = 60.0f; // where it blows toward, clockwise from -z (north) toward +x
    float gustStrength = 0.5f;      // gust peak as a fraction of speed
    float gustSpeed = 5.0f;         // metres per second the gust fronts travel
    float turbulence = 0.2f;        // small-scale noise as a fraction of speed, in [0, 1]
    bool operator==(const Wind&) const = default;
};

// The horizontal unit vector the wind blows along (directionDegrees).
glm::vec3 windHeading(const Wind& wind);
// Metres per second the mean wind blows (its gusts and turbulence left out):
// `speed` along windHeading.
glm::vec3 meanWindVelocity(const Wind& wind);

// The most joints a scene or --joint-budget may give near plants: their
// states and poses take 64 bytes a joint (640 MB here), and every simulated
// array is read through texel views of at most 2²⁷ texels on common devices.
constexpr uint32_t kMaxJointBudget = 10'000'000;

// The physical model of the plants (docs/PHYSICS.md).
struct PhysicsSettings {
    float woodDensity = 600.0f;    // kg/m³ (Crankshaw 2020: 400–1000)
    float youngsModulus = 1.0e9f;  // Pa, of green wood, for stiffness from beam theory
    float stiffnessScale = 1.0f;   // multiplies every stiffness (art direction: >1 stiffer)
    float dampingRatio = 0.15f;    // ζ: c = 2·ζ·sqrt(k·I)
    float gravity = 9.8f;          // m/s²
    float airDensity = 1.2f;       // kg/m³
    float dragCoefficient = 1.0f;  // Cd of segments
    float leafDrag = 1.0f;         // multiplies the drag area of leaves and blades
    float subStep = 1.0f / 240.0f; // s, the fixed integration step
    uint32_t jointBudget = 200000; // simulated joints of plants near the camera, each its own state
    uint32_t sharedPhases = 4;     // simulated copies per plant model shared by farther plants
    bool operator==(const PhysicsSettings&) const = default;
};

// The latest scene time --time takes, and the widest a camera key's time may
// be either side of 0: the shaders' float time still steps by under 10 ms
// there (2^-7 s at 10^5 s), so the wind's motion stays smooth.
inline constexpr double kMaxSceneTime = 100000.0;
// How far from the origin a camera key's position and target may be: float
// positions there are still a metre apart, so a field of a few hundred metres
// is still placed in view (and depth) from there.
inline constexpr float kMaxCameraCoordinate = 1e7f;
// The bounds of a scene's other numbers (scene_json.cpp): lengths and sizes
// in metres up to 10^6 (a terrain 1 000 km across), angles in degrees within
// ±10^6, and scales, rates, intensities and physical constants up to 10^6
// (Young's modulus, in pascals, has a bound of its own). A product of a few
// of them — a drag force is density times speed squared times a coefficient —
// stays far inside float's 3.4·10^38.
inline constexpr double kMaxSceneLength = 1e6;
inline constexpr double kMaxSceneAngle = 1e6;
inline constexpr double kMaxSceneFactor = 1e6;
// The least time between two camera keys: the spline's tangents, position
// differences over key spacings, then stay far inside float's range.
inline constexpr double kMinKeyframeSpacing = 1e-3;

struct CameraKeyframe {
    double time = 0.0; // seconds, strictly increasing along the path
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
    std::optional<float> fovYDegrees; // empty: the path's
    bool operator==(const CameraKeyframe&) const = default;
};

struct CameraPath {
    std::vector<CameraKeyframe> keyframes; // empty: the default orbit of cameraAt
    float fovYDegrees = 45.0f;
    float nearPlane = 0.1f;
    float farPlane = 2000.0f;
    bool operator==(const CameraPath&) const = default;
};

// A cloud in the sky: the spheres of an L-system (engine/scene/cloud_spheres.h,
// docs/CLOUDS.md), drifting with the wind.
struct Cloud {
    std::filesystem::path lsystem;    // resolved against the scene file's folder; exists
    glm::vec3 position{0.0f};         // metres: the middle of the cloud's bottom at scene time 0
    float size = 200.0f;              // metres across the cloud's widest side
    std::optional<uint32_t> seed;     // empty: the L-system's own
    bool shadow = false;              // casts a shadow on the ground (engine/scene/cloud_shadow.h)
    std::vector<CloudSphere> spheres; // derived as loadScene reads the cloud, in world metres at time 0
    bool operator==(const Cloud&) const = default;
};

struct Scene {
    std::filesystem::path file; // the file it was loaded from
    std::string description;
    uint32_t seed = 0;
    Terrain terrain;
    std::vector<Species> species; // never empty after loadScene
    Sun sun;
    Sky sky;
    Fog fog;
    Wind wind;
    PhysicsSettings physics;
    CameraPath camera;
    std::vector<Cloud> clouds;
    bool operator==(const Scene&) const = default;
};

// Reads and validates a scene file; throws SceneError naming file:line:column,
// the JSON pointer of the value at fault and what was expected, and
// lsys::MemoryBudgetError when the parsed file would not fit `memory`.
Scene loadScene(const std::filesystem::path& file, const lsys::MemoryBudget& memory = {});

// The camera on the path at time t (seconds): a Catmull-Rom spline through the
// keyframes with tangents from the neighbouring keys' times, held at the first
// and last keyframe outside them (NaN is the first). An empty path orbits the origin.
Camera cameraAt(const CameraPath& path, double t);

// `count` scene times spread evenly over the path: from its first keyframe to
// its last, both included (a single time is the first keyframe's); without
// keyframes, steps through one turn of the default orbit from t = 0.
std::vector<double> timesAlongPath(const CameraPath& path, uint32_t count);

// Seeds that the file leaves out come from the scene seed, one independent
// stream each, so changing the scene seed changes the whole scene.
uint32_t terrainSeed(const Scene& scene);
uint32_t speciesSeed(const Scene& scene, size_t species); // its first variant's L-system seed

// Whether a plant file is a model a species takes as `model` (a ramification
// tree, .ram.json, or a component plant, .comp.json): built, not derived.
bool isPlantModelFile(const std::filesystem::path& file);
uint32_t placementSeed(const Scene& scene, size_t species);

// The sun, sky, fog and ground settings the renderer's frame uniforms take.
Environment environmentOf(const Scene& scene);

} // namespace pf
