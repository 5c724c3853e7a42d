// loadScene: the sections of a scene file (docs/SCENE_FORMAT.md), each read
// onto its struct's defaults, so a key left out keeps the default.
#include "engine/scene/scene.h"

#include "lsystem/common/json_reader.h"
#include "lsystem/landscape/mountain_turtle.h"
#include "lsystem/turtle/turtle_builder.h"
#include "lsystem/vlab/object.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

namespace pf {
// The located JSON reader (lsystem/common/json_reader.h).
using lsys::anyNumber, lsys::arrayElements, lsys::atLeast, lsys::between, lsys::didYouMean, lsys::failAt,
    lsys::JsonError, lsys::JsonNode, lsys::JsonSource, lsys::member, lsys::Range, lsys::readField, lsys::readJsonFile,
    lsys::readNumber, lsys::readString, lsys::readVector, lsys::requireMap, lsys::requireMember, lsys::requireObject,
    lsys::rootNode;
namespace {

// Every number of a scene has a bound, so that what is computed from it —
// squares, products of a few, a light times a colour — stays far inside
// float's range and no NaN or infinity reaches a frame, a statistic or an
// export. The bounds are orders of magnitude past any forest.
const Range kColor = between(0.0, kMaxSceneFactor); // linear RGB; above 1 is allowed for bright light
// A position or an offset, in metres: as far out as a camera may be.
const Range kCoordinate = between(-kMaxCameraCoordinate, kMaxCameraCoordinate);
// A length, a height, a distance or a size, in metres.
const Range kLength = Range{.min = 0.0, .max = kMaxSceneLength, .minOpen = true};
const Range kLengthOrZero = between(0.0, kMaxSceneLength);
// An angle, in degrees: any turn, within what float holds to a degree.
const Range kAngle = between(-kMaxSceneAngle, kMaxSceneAngle);
// A scale, a rate, an intensity or a physical constant: positive or zero.
const Range kFactor = Range{.min = 0.0, .max = kMaxSceneFactor, .minOpen = true};
const Range kFactorOrZero = between(0.0, kMaxSceneFactor);

// A file (or, where `folders` allows, a folder: a vlab object) that exists,
// relative to the scene file's folder.
std::filesystem::path existingFile(const JsonNode& node, const std::filesystem::path& sceneFolder,
                                   bool folders = false) {
    const std::string name = readString(node);
    if (name.empty()) failAt(node, "must be a file name");
    const std::filesystem::path path = (sceneFolder / name).lexically_normal();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) && !(folders && std::filesystem::is_directory(path, error)))
        failAt(node, std::string("names a ") + (folders ? "file or folder" : "file") +
                         " that does not exist: " + path.string() + " (paths are relative to the scene file)");
    return path;
}

// A [low, high] pair with low ≤ high.
void readInterval(const JsonNode& object, std::string_view key, glm::vec2& out, Range range) {
    const std::optional<JsonNode> node = member(object, key);
    if (!node) return;
    out = readVector<2>(*node, range);
    if (out.x > out.y) failAt(*node, "must be [low, high] with low ≤ high");
}

NoiseHeightfield readNoise(const JsonNode& node) {
    requireObject(node, {"seed", "octaves", "amplitude", "frequency", "lacunarity", "gain"});
    NoiseHeightfield noise;
    readField(node, "seed", noise.seed, anyNumber());
    readField(node, "octaves", noise.octaves, between(1, 16));
    readField(node, "amplitude", noise.amplitude, kLengthOrZero);
    readField(node, "frequency", noise.frequency, kFactor);
    readField(node, "lacunarity", noise.lacunarity, between(1.0, 16.0)); // 16^15 at 16 octaves
    readField(node, "gain", noise.gain, between(0.0, 1.0));
    return noise;
}

ImageHeightfield readImage(const JsonNode& node, const std::filesystem::path& sceneFolder) {
    requireObject(node, {"path", "height_scale"});
    ImageHeightfield image;
    image.path = existingFile(requireMember(node, "path", "a greyscale PNG file"), sceneFolder);
    readField(node, "height_scale", image.heightScale, kLengthOrZero);
    return image;
}

// The bumps of the terrain's L-system, derived now so that a malformed file,
// a bump past max_height or too many bumps are errors at `node`.
std::vector<lsys::landscape::TerrainBump> mountainsOf(const TerrainLsystem& lsystem, const JsonNode& node) {
    const lsys::vlab::PlantFile file = lsys::vlab::loadPlant(lsystem.path);
    if (!file.parsed.ok())
        failAt(node, "names a malformed L-system:\n" + lsys::formatDiagnostics(file.parsed.diagnostics, file.source));
    lsys::landscape::MountainPlacement placement;
    placement.originX = lsystem.origin.x;
    placement.originZ = lsystem.origin.y;
    placement.headingDegrees = lsystem.headingDegrees;
    placement.scale = lsystem.scale;
    placement.maxHeight = lsystem.maxHeight;
    try {
        return lsys::landscape::mountainBumpsOf(file.parsed.grammar, placement, lsystem.seed);
    } catch (const lsys::MemoryBudgetError&) { // the machine's limit, not the file's fault: its type kept
        throw;
    } catch (const lsys::DerivationError& error) {
        failAt(node, "(" + lsystem.path.string() + ") cannot be made into mountains: " + error.what());
    }
}

// A file name, or an object of a file name and where its turtle stands.
TerrainLsystem readTerrainLsystem(const JsonNode& node, const std::filesystem::path& sceneFolder) {
    TerrainLsystem lsystem;
    if (!node.value->is_object()) {
        lsystem.path = existingFile(node, sceneFolder, true);
    } else {
        requireObject(node, {"path", "origin", "heading", "scale", "max_height", "seed"});
        lsystem.path = existingFile(requireMember(node, "path", "an L-system file"), sceneFolder, true);
        readField(node, "origin", lsystem.origin, kCoordinate);
        readField(node, "heading", lsystem.headingDegrees, kAngle);
        readField(node, "scale", lsystem.scale, kLength);
        readField(node, "max_height", lsystem.maxHeight, kLength);
        readField(node, "seed", lsystem.seed, anyNumber());
    }
    lsystem.bumps = mountainsOf(lsystem, node);
    return lsystem;
}

Terrain readTerrain(const JsonNode& node, const std::filesystem::path& sceneFolder) {
    requireObject(node, {"size", "resolution", "noise", "image", "lsystem", "albedo"});
    Terrain terrain;
    readField(node, "size", terrain.size, kLength);
    readField(node, "resolution", terrain.resolution, between(2, kMaxTerrainResolution));
    readField(node, "albedo", terrain.albedo, between(0.0, 1.0));
    const std::optional<JsonNode> noise = member(node, "noise");
    const std::optional<JsonNode> image = member(node, "image");
    if (noise && image)
        failAt(*image, "cannot be given together with \"noise\": the heightfield is one or the other", true);
    if (noise) terrain.heightfield = readNoise(*noise);
    if (image) terrain.heightfield = readImage(*image, sceneFolder);
    if (const std::optional<JsonNode> lsystem = member(node, "lsystem")) {
        terrain.lsystem = readTerrainLsystem(*lsystem, sceneFolder);
        if (!noise && !image) terrain.heightfield = NoiseHeightfield{.amplitude = 0.0f}; // flat ground under the bumps
    }
    return terrain;
}

PlacedPlant readPlacedPlant(const JsonNode& node) {
    requireObject(node, {"position", "rotation", "scale"});
    PlacedPlant plant;
    plant.position = readVector<2>(requireMember(node, "position", "[x, z] in metres"), kCoordinate);
    readField(node, "rotation", plant.rotationDegrees, kAngle);
    readField(node, "scale", plant.scale, kFactor);
    return plant;
}

// In PlacementMode's order.
const char* const kPlacementModeKeys[] = {"density", "min_distance", "count", "instances"};

// Reads onto inherited: a species' placement starts from the global one, and
// its way of counting plants (one of kPlacementModeKeys) replaces the inherited one.
Placement readPlacement(const JsonNode& node, Placement inherited) {
    requireObject(node, {"density", "min_distance", "count", "instances", "clearance", "max_slope", "height_range",
                         "scale", "seed"});
    Placement placement = std::move(inherited);
    std::optional<JsonNode> modeNode;
    for (size_t mode = 0; mode < std::size(kPlacementModeKeys); ++mode) {
        const std::optional<JsonNode> given = member(node, kPlacementModeKeys[mode]);
        if (!given) continue;
        if (modeNode)
            failAt(*given,
                   "cannot be given together with \"" + modeNode->path.back() +
                       "\": density, min_distance, count and instances are alternatives",
                   true);
        modeNode = given;
        placement.mode = PlacementMode(mode);
        placement.instances.clear(); // only an explicit placement keeps a list
    }
    readField(node, "density", placement.densityPerHectare, between(0.0, 1e8)); // one plant a cm²
    readField(node, "min_distance", placement.minDistance, kLength);
    readField(node, "count", placement.count, anyNumber());
    if (const std::optional<JsonNode> instances = member(node, "instances")) {
        for (const JsonNode& element : arrayElements(*instances, "an array of plants"))
            placement.instances.push_back(readPlacedPlant(element));
    }
    readField(node, "clearance", placement.clearance, kLengthOrZero);
    readField(node, "max_slope", placement.maxSlopeDegrees, between(0.0, 90.0));
    readInterval(node, "height_range", placement.heightRange, kCoordinate);
    readInterval(node, "scale", placement.scaleRange, kFactor);
    readField(node, "seed", placement.seed, anyNumber());
    return placement;
}

const char* const kBillboardNames[] = {"single", "double", "triple"};

LodHints readLod(const JsonNode& node) {
    requireObject(node, {"billboard", "reduced_below_px", "impostor_below_px", "hidden_below_px"});
    LodHints lod;
    if (const std::optional<JsonNode> billboard = member(node, "billboard")) {
        const std::string name = readString(*billboard);
        const std::vector<std::string_view> names(std::begin(kBillboardNames), std::end(kBillboardNames));
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end())
            failAt(*billboard,
                   "must be \"single\", \"double\" or \"triple\" (got \"" + name + "\")" + didYouMean(name, names));
        lod.billboard = BillboardKind(it - names.begin());
    }
    readField(node, "reduced_below_px", lod.reducedBelowPixels, kFactor);
    readField(node, "impostor_below_px", lod.impostorBelowPixels, kFactor);
    readField(node, "hidden_below_px", lod.hiddenBelowPixels, kFactorOrZero);
    if (lod.impostorBelowPixels > lod.reducedBelowPixels)
        failAt(node, "needs impostor_below_px ≤ reduced_below_px (impostors are the farthest level)");
    if (lod.hiddenBelowPixels > lod.impostorBelowPixels)
        failAt(node, "needs hidden_below_px ≤ impostor_below_px (hidden plants are farther than impostors)");
    return lod;
}

bool isIndex(std::string_view key) {
    return !key.empty() && key.size() <= 3 &&
           std::all_of(key.begin(), key.end(), [](char c) { return std::isdigit((unsigned char)c); }) &&
           std::stoi(std::string(key)) <= 255;
}

// Keys are palette names ("leaf") or indices ("9"); the palette repeats past 7.
std::vector<MaterialOverride> readMaterials(const JsonNode& node) {
    requireMap(node);
    std::vector<std::string_view> names;
    for (const lsys::Material& m : lsys::defaultPalette()) names.push_back(m.name);
    std::vector<MaterialOverride> materials;
    for (const auto& [key, value] : node.value->items()) {
        const JsonNode entry = *member(node, key);
        MaterialOverride material;
        const auto named = std::find(names.begin(), names.end(), key);
        if (named != names.end()) {
            material.index = uint32_t(named - names.begin());
        } else if (isIndex(key)) {
            material.index = uint32_t(std::stoi(key));
        } else {
            failAt(entry,
                   "is not a material: use a palette name (bark, leaf, …) or an index 0-255" + didYouMean(key, names),
                   true);
        }
        if (std::any_of(materials.begin(), materials.end(),
                        [&](const MaterialOverride& m) { return m.index == material.index; }))
            failAt(entry, "names a material already given", true);
        material.albedo = readVector<3>(entry, between(0.0, 1.0));
        materials.push_back(material);
    }
    std::sort(materials.begin(), materials.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
    return materials;
}

bool isConstantName(std::string_view name) {
    return !name.empty() && !std::isdigit((unsigned char)name[0]) &&
           std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_'; });
}

std::map<std::string, double> readDefines(const JsonNode& node) {
    requireMap(node);
    std::map<std::string, double> defines;
    for (const auto& [key, value] : node.value->items()) {
        const JsonNode entry = *member(node, key);
        if (!isConstantName(key)) failAt(entry, "is not a constant name (letters, digits and _)", true);
        defines[key] = readNumber(entry, anyNumber());
    }
    return defines;
}

// A species' plant: "lsystem" (with its "defines" and "steps") or "model",
// a ramification tree (.ram.json) or a component plant (.comp.json); exactly one.
void readPlantSource(const JsonNode& node, const std::filesystem::path& sceneFolder, Species& species) {
    const std::optional<JsonNode> lsystem = member(node, "lsystem");
    const std::optional<JsonNode> model = member(node, "model");
    if (lsystem && model) failAt(*model, "and \"lsystem\" both give the plant; keep one", true);
    if (!model) {
        species.lsystem =
            existingFile(requireMember(node, "lsystem", "the L-system file or vlab object folder, or a \"model\""),
                         sceneFolder, true);
        if (auto defines = member(node, "defines")) species.defines = readDefines(*defines);
        readField(node, "steps", species.steps, between(0, 1000));
        return;
    }
    for (const std::string_view key : {"defines", "steps"})
        if (auto lsystemKey = member(node, key))
            failAt(*lsystemKey, "is an L-system setting; a species with a \"model\" has none", true);
    const std::filesystem::path name = readString(*model);
    if (!isPlantModelFile(name))
        failAt(*model, "must name a ramification tree (.ram.json) or a component plant (.comp.json), not \"" +
                           name.filename().string() + "\"");
    species.model = existingFile(*model, sceneFolder);
}

Species readSpecies(const JsonNode& node, const std::filesystem::path& sceneFolder, const Placement& globalPlacement) {
    requireObject(node, {"name", "lsystem", "model", "defines", "steps", "variants", "seed", "height", "lod",
                         "materials", "placement"});
    Species species;
    species.name = readString(requireMember(node, "name", "a name for the species"));
    if (species.name.empty()) failAt(*member(node, "name"), "must not be empty");
    readPlantSource(node, sceneFolder, species);
    readField(node, "variants", species.variants, between(1, 1024));
    readField(node, "seed", species.seed, anyNumber());
    readField(node, "height", species.height, kLength);
    if (auto lod = member(node, "lod")) species.lod = readLod(*lod);
    if (auto materials = member(node, "materials")) species.materials = readMaterials(*materials);
    const std::optional<JsonNode> placement = member(node, "placement");
    species.placement = placement ? readPlacement(*placement, globalPlacement) : globalPlacement;
    return species;
}

Sun readSun(const JsonNode& node) {
    requireObject(node, {"elevation", "azimuth", "colour", "intensity"});
    Sun sun;
    readField(node, "elevation", sun.elevationDegrees, between(-90.0, 90.0));
    readField(node, "azimuth", sun.azimuthDegrees, kAngle);
    readField(node, "colour", sun.color, kColor);
    readField(node, "intensity", sun.intensity, kFactorOrZero);
    return sun;
}

Sky readSky(const JsonNode& node) {
    requireObject(node, {"zenith", "horizon"});
    Sky sky;
    readField(node, "zenith", sky.zenith, kColor);
    readField(node, "horizon", sky.horizon, kColor);
    return sky;
}

Fog readFog(const JsonNode& node) {
    requireObject(node, {"density"});
    Fog fog;
    readField(node, "density", fog.density, kFactorOrZero);
    return fog;
}

Wind readWind(const JsonNode& node) {
    requireObject(node, {"speed", "direction", "gust_strength", "gust_speed", "turbulence"});
    Wind wind;
    readField(node, "speed", wind.speed, kFactorOrZero);
    readField(node, "direction", wind.directionDegrees, kAngle);
    readField(node, "gust_strength", wind.gustStrength, kFactorOrZero);
    readField(node, "gust_speed", wind.gustSpeed, kFactorOrZero);
    readField(node, "turbulence", wind.turbulence, between(0.0, 1.0));
    return wind;
}

PhysicsSettings readPhysics(const JsonNode& node) {
    requireObject(node, {"wood_density", "youngs_modulus", "stiffness_scale", "damping_ratio", "gravity", "air_density",
                         "drag_coefficient", "leaf_drag", "sub_step", "joint_budget", "shared_phases"});
    PhysicsSettings physics;
    readField(node, "wood_density", physics.woodDensity, kFactor);
    readField(node, "youngs_modulus", physics.youngsModulus,
              Range{.min = 0.0, .max = 1e13, .minOpen = true}); // steel: 2·10^11 Pa
    readField(node, "stiffness_scale", physics.stiffnessScale, kFactor);
    readField(node, "damping_ratio", physics.dampingRatio, between(0.0, 10.0));
    readField(node, "gravity", physics.gravity, kFactorOrZero);
    readField(node, "air_density", physics.airDensity, kFactorOrZero);
    readField(node, "drag_coefficient", physics.dragCoefficient, kFactorOrZero);
    readField(node, "leaf_drag", physics.leafDrag, kFactorOrZero);
    // Above 1/30 s a frame would need less than one step; below 1/10000 s a frame costs hundreds.
    readField(node, "sub_step", physics.subStep, between(1.0 / 10000.0, 1.0 / 30.0));
    readField(node, "joint_budget", physics.jointBudget, between(0.0, double(kMaxJointBudget)));
    readField(node, "shared_phases", physics.sharedPhases, between(1, 64));
    return physics;
}

const Range kFov = {.min = 0.0, .max = 180.0, .minOpen = true, .maxOpen = true};

CameraKeyframe readKeyframe(const JsonNode& node) {
    requireObject(node, {"time", "position", "target", "fov"});
    CameraKeyframe key;
    key.time = readNumber(requireMember(node, "time", "seconds"), between(-kMaxSceneTime, kMaxSceneTime));
    const Range coordinate = between(-kMaxCameraCoordinate, kMaxCameraCoordinate);
    key.position = readVector<3>(requireMember(node, "position", "[x, y, z] in metres"), coordinate);
    key.target = readVector<3>(requireMember(node, "target", "[x, y, z] in metres"), coordinate);
    readField(node, "fov", key.fovYDegrees, kFov);
    if (key.position == key.target) failAt(*member(node, "target"), "must differ from position");
    return key;
}

CameraPath readCamera(const JsonNode& node) {
    requireObject(node, {"fov", "near", "far", "keyframes"});
    CameraPath camera;
    readField(node, "fov", camera.fovYDegrees, kFov);
    readField(node, "near", camera.nearPlane, kLength);
    readField(node, "far", camera.farPlane, Range{.min = camera.nearPlane, .max = kMaxSceneLength, .minOpen = true});
    if (const std::optional<JsonNode> keyframes = member(node, "keyframes")) {
        for (const JsonNode& element : arrayElements(*keyframes, "an array of keyframes")) {
            CameraKeyframe key = readKeyframe(element);
            if (!camera.keyframes.empty() && !(key.time >= camera.keyframes.back().time + kMinKeyframeSpacing))
                failAt(*member(element, "time"), "must be at least " +
                                                     (std::ostringstream() << kMinKeyframeSpacing).str() +
                                                     " s later than the previous keyframe's time");
            camera.keyframes.push_back(key);
        }
    }
    return camera;
}

// The cloud's spheres are derived here, so a malformed or oversized cloud
// L-system is reported at its "lsystem" value.
Cloud readCloud(const JsonNode& node, const std::filesystem::path& sceneFolder) {
    requireObject(node, {"lsystem", "position", "size", "seed", "shadow"});
    Cloud cloud;
    const JsonNode lsystem = requireMember(node, "lsystem", "the cloud's L-system file (data/clouds)");
    cloud.lsystem = existingFile(lsystem, sceneFolder);
    cloud.position = readVector<3>(requireMember(node, "position", "[x, y, z] in metres"), kCoordinate);
    readField(node, "size", cloud.size, kLength);
    readField(node, "seed", cloud.seed, anyNumber());
    readField(node, "shadow", cloud.shadow);
    try {
        cloud.spheres = cloudSpheres(cloud.lsystem, cloud.seed, cloud.size, cloud.position);
    } catch (const CloudError& error) {
        failAt(lsystem, std::string("makes no cloud: ") + error.what());
    }
    return cloud;
}

void readClouds(const JsonNode& node, const std::filesystem::path& sceneFolder, std::vector<Cloud>& clouds) {
    size_t spheres = 0;
    for (const JsonNode& element : arrayElements(node, "an array of clouds")) {
        clouds.push_back(readCloud(element, sceneFolder));
        spheres += clouds.back().spheres.size();
        if (spheres > kMaxSceneCloudSpheres)
            failAt(element, "brings the scene's clouds to " + std::to_string(spheres) + " spheres, more than the " +
                                std::to_string(kMaxSceneCloudSpheres) + " a scene may have");
    }
}

void requireUniqueNames(const std::vector<Species>& species, const std::vector<JsonNode>& elements) {
    std::map<std::string_view, size_t> first; // each name's first species
    for (size_t i = 0; i < species.size(); ++i)
        if (const auto [named, added] = first.try_emplace(species[i].name, i); !added)
            failAt(*member(elements[i], "name"), "repeats the name of /species/" + std::to_string(named->second));
}

Scene readScene(const std::filesystem::path& file, const lsys::MemoryBudget& memory) {
    // A million explicitly placed plants take about 60 MB of JSON.
    const JsonSource source = readJsonFile(file, {"scene", size_t(256) << 20}, memory);
    const JsonNode root = rootNode(source);
    requireObject(root, {"description", "seed", "terrain", "species", "placement", "sun", "sky", "fog", "wind",
                         "physics", "camera", "clouds"});
    const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();

    Scene scene;
    scene.file = file;
    readField(root, "description", scene.description);
    readField(root, "seed", scene.seed, anyNumber());
    if (auto terrain = member(root, "terrain")) scene.terrain = readTerrain(*terrain, folder);

    const std::optional<JsonNode> globalNode = member(root, "placement");
    const Placement globalPlacement = globalNode ? readPlacement(*globalNode, {}) : Placement{};
    const JsonNode list = requireMember(root, "species", "an array of plant species");
    const std::vector<JsonNode> elements = arrayElements(list, "an array of plant species");
    for (const JsonNode& element : elements) scene.species.push_back(readSpecies(element, folder, globalPlacement));
    if (scene.species.empty()) failAt(list, "must list at least one species");
    requireUniqueNames(scene.species, elements);

    if (auto sun = member(root, "sun")) scene.sun = readSun(*sun);
    if (auto sky = member(root, "sky")) scene.sky = readSky(*sky);
    if (auto fog = member(root, "fog")) scene.fog = readFog(*fog);
    if (auto wind = member(root, "wind")) scene.wind = readWind(*wind);
    if (auto physics = member(root, "physics")) scene.physics = readPhysics(*physics);
    if (auto camera = member(root, "camera")) scene.camera = readCamera(*camera);
    if (auto clouds = member(root, "clouds")) readClouds(*clouds, folder, scene.clouds);
    return scene;
}

} // namespace

Scene loadScene(const std::filesystem::path& file, const lsys::MemoryBudget& memory) {
    try {
        return readScene(file, memory);
    } catch (const JsonError& error) {
        throw SceneError(error.what());
    }
}

} // namespace pf
