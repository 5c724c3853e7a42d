#include "engine/scene/field_content.h"

#include "engine/scene/clusters.h"
#include "engine/scene/natural_density.h"

#include <glm/glm.hpp>

#include <algorithm>

#include <numbers>

namespace pf {

namespace {

// The noise or image heightfield, before the L-system's bumps are added.
Heightfield baseTerrainOf(const Scene& scene, const lsys::MemoryBudget& memory) {
    const Terrain& t = scene.terrain;
    if (const auto* image = std::get_if<ImageHeightfield>(&t.heightfield))
        return loadImageTerrain(image->path.string(), t.size, image->heightScale, memory);
    const auto& noise = std::get<NoiseHeightfield>(t.heightfield);
    NoiseTerrainSettings settings;
    settings.resolution = t.resolution;
    settings.size = t.size;
    settings.seed = noise.seed.value_or(terrainSeed(scene));
    settings.octaves = noise.octaves;
    settings.frequency = noise.frequency;
    settings.amplitude = noise.amplitude;
    settings.lacunarity = noise.lacunarity;
    settings.gain = noise.gain;
    settings.memory = memory;
    return makeNoiseTerrain(settings);
}

PlacementRule ruleOf(const Scene& scene, size_t speciesIndex) {
    const Species& species = scene.species[speciesIndex];
    const Placement& p = species.placement;
    PlacementRule rule;
    rule.species = uint32_t(speciesIndex);
    switch (p.mode) {
    case PlacementMode::Density: rule.densityPerHectare = p.densityPerHectare; break;
    case PlacementMode::Distance: rule.minDistance = p.minDistance; break;
    case PlacementMode::Count:
        // The density that would give `count` plants over the whole square;
        // slope and height limits then remove some.
        rule.densityPerHectare = float(p.count) * 10000.0f / (scene.terrain.size * scene.terrain.size);
        break;
    case PlacementMode::Explicit: break;
    }
    rule.clearance = p.clearance;
    rule.maxSlopeDegrees = p.maxSlopeDegrees;
    rule.minHeight = p.heightRange.x;
    rule.maxHeight = p.heightRange.y;
    rule.minScale = p.scaleRange.x;
    rule.maxScale = p.scaleRange.y;
    rule.variants = species.variants;
    rule.seed = placementSeed(scene, speciesIndex);
    return rule;
}

// Listed plants: on the terrain, with a variant and wind phase from their index.
void appendExplicit(const Scene& scene, const Heightfield& terrain, size_t speciesIndex,
                    std::vector<PlantInstance>& out) {
    const Species& species = scene.species[speciesIndex];
    for (size_t i = 0; i < species.placement.instances.size(); ++i) {
        const PlacedPlant& placed = species.placement.instances[i];
        PlantInstance plant;
        plant.position = {placed.position.x, heightAt(terrain, placed.position.x, placed.position.y),
                          placed.position.y};
        plant.rotation = glm::radians(placed.rotationDegrees);
        plant.scale = placed.scale;
        plant.species = uint32_t(speciesIndex);
        plant.variant = uint32_t(i % species.variants);
        plant.windPhase = float(std::fmod(double(i) * 2.399963, 2.0 * std::numbers::pi)); // golden angle
        out.push_back(plant);
    }
}

// A density of zero or a count of zero asks for no plant: it has no rule (a
// rule's zero density means "use the distance", which would fill the terrain).
bool placesNothing(const Placement& p) {
    return (p.mode == PlacementMode::Density && p.densityPerHectare == 0.0f) ||
           (p.mode == PlacementMode::Count && p.count == 0);
}

} // namespace

Heightfield terrainOf(const Scene& scene, const lsys::MemoryBudget& memory) {
    Heightfield terrain = baseTerrainOf(scene, memory);
    if (scene.terrain.lsystem)
        lsys::landscape::addBumps(terrain.heights, terrain.resolution, terrain.size, scene.terrain.lsystem->bumps);
    return terrain;
}

std::vector<PlacementRule> placementRules(const Scene& scene) {
    std::vector<PlacementRule> rules;
    for (size_t i = 0; i < scene.species.size(); ++i) {
        const Placement& placement = scene.species[i].placement;
        if (placement.mode != PlacementMode::Explicit && !placesNothing(placement)) rules.push_back(ruleOf(scene, i));
    }
    return rules;
}

uint64_t placementBytes(uint64_t plants) { return lsys::bytesTimes(plants, 4 * sizeof(PlantInstance)); }

PlacedField placeField(const Scene& scene, std::optional<PlantCount> count, const lsys::MemoryBudget& memory) {
    if (count) lsys::need(memory, "placement", placementBytes(count->plants));
    const std::vector<PlacementRule> rules = placementRules(scene);
    const uint64_t seed = placementSeed(scene, 0);
    PlacedField field;
    field.terrain = scene.terrain;
    std::vector<PlantInstance> generated;
    if (count && count->mode == CountMode::NaturalDensity && !rules.empty()) {
        NaturalField natural = placeAtNaturalDensity(scene, rules, count->plants, seed, memory);
        field.terrain = natural.terrain;
        field.heightfield = std::move(natural.heightfield);
        field.note = std::move(natural.note);
        generated = std::move(natural.plants);
    } else {
        field.heightfield = terrainOf(scene, memory);
        if (!rules.empty())
            generated = count ? scaleToCount(field.heightfield, rules, count->plants, seed)
                              : placeSpecies(field.heightfield, rules, seed, memory);
    }

    // Group by species in scene order: generated plants are already grouped
    // by rule, and rules follow scene order; explicit species slot in.
    field.plants.reserve(generated.size());
    size_t next = 0;
    for (size_t s = 0; s < scene.species.size(); ++s) {
        if (scene.species[s].placement.mode == PlacementMode::Explicit) {
            appendExplicit(scene, field.heightfield, s, field.plants);
            continue;
        }
        while (next < generated.size() && generated[next].species == s) field.plants.push_back(generated[next++]);
    }
    return field;
}

FieldContent buildFieldContent(const Scene& scene, std::optional<PlantCount> count, const ModelProgress& progress,
                               const lsys::MemoryBudget& memory, ModelAssets assets) {
    PlacedField field = placeField(scene, count, memory);
    FieldContent content;
    content.scene = scene;
    content.scene.terrain = field.terrain;
    content.terrain = std::move(field.heightfield);
    content.plants = std::move(field.plants);
    sortPlantsByCluster(content.plants, clusterRoot(content.terrain));
    content.note = std::move(field.note);
    content.models = buildPlantModels(scene, progress, memory, assets);
    return content;
}

std::vector<gpu::FieldInstance> fieldInstancesOf(const FieldContent& content) {
    std::vector<gpu::FieldInstance> instances;
    instances.reserve(content.plants.size());
    for (const PlantInstance& p : content.plants)
        instances.push_back({glm::vec4(p.position, p.scale), glm::vec4(p.rotation, p.windPhase, 0.0f, 0.0f),
                             glm::uvec4(content.models.modelOf(p.species, p.variant), p.species, p.variant, 0u)});
    return instances;
}

SceneBox fieldBox(const FieldContent& content) {
    const Heightfield& terrain = content.terrain;
    const auto [lowest, highest] = std::minmax_element(terrain.heights.begin(), terrain.heights.end());
    SceneBox box;
    box.min = glm::vec3(-0.5f * terrain.size, lowest == terrain.heights.end() ? 0.0f : *lowest, -0.5f * terrain.size);
    box.max = glm::vec3(0.5f * terrain.size, highest == terrain.heights.end() ? 0.0f : *highest, 0.5f * terrain.size);
    // Each plant within its model's bounding sphere turned about the plant's axis: a sphere about the plant's
    // base as wide as the sphere's centre is far from it, plus its radius.
    for (const PlantInstance& plant : content.plants) {
        const glm::vec4 sphere = content.models.models[content.models.modelOf(plant.species, plant.variant)].gpu.sphere;
        const float reach = (glm::length(glm::vec3(sphere)) + sphere.w) * plant.scale;
        box.min = glm::min(box.min, plant.position - reach);
        box.max = glm::max(box.max, plant.position + reach);
    }
    return box;
}

} // namespace pf
