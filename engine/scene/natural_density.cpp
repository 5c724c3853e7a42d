#include "engine/scene/natural_density.h"

#include "engine/scene/scene.h"

#include "engine/scene/field_content.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pf {

namespace {

// Side length to spare on each growth (1 % of the side, 2 % of the plants),
// so one placement nearly always holds the count.
constexpr double kGrowthMargin = 1.01;
// Growths before giving up; each one corrects by the measured shortfall, so
// a second is rare and a third has never been needed.
constexpr int kMaxGrowths = 6;

std::string countText(size_t n) { return std::to_string(n) + (n == 1 ? " plant" : " plants"); }

} // namespace

Terrain grownTerrain(const Terrain& terrain, float side, size_t maxSamples) {
    if (!std::holds_alternative<NoiseHeightfield>(terrain.heightfield) || !(side > terrain.size)) return terrain;
    Terrain grown = terrain;
    grown.size = side;
    const double spacing = double(terrain.size) / double(terrain.resolution - 1);
    const double mostPerSide = std::min(std::floor(std::sqrt(double(maxSamples))), double(kMaxTerrainResolution));
    const double samples = std::min(std::ceil(double(side) / spacing) + 1.0, mostPerSide);
    grown.resolution = std::max(terrain.resolution, uint32_t(samples));
    return grown;
}

NaturalField placeAtNaturalDensity(const Scene& scene, std::span<const PlacementRule> rules, size_t count,
                                   uint64_t seed, const lsys::MemoryBudget& memory) {
    NaturalField field{scene.terrain, terrainOf(scene, memory), {}, {}};
    const std::vector<PlantInstance> natural = placeSpecies(field.heightfield, rules, seed, memory);
    if (natural.empty())
        throw SceneError("placement: the rules admit no plant on this terrain"); // the scene's fault: exit 2
    if (count <= natural.size()) {
        field.plants = keepCentralSquare(natural, count);
        return field;
    }
    if (std::holds_alternative<ImageHeightfield>(scene.terrain.heightfield)) {
        field.note = "the image terrain cannot grow: " + countText(count) + " densified on its " +
                     std::to_string(int(std::lround(scene.terrain.size))) + " m square, which holds " +
                     countText(natural.size()) + " at the scene's densities";
        field.plants = scaleToCount(field.heightfield, rules, count, seed);
        return field;
    }
    // Plants are proportional to area: the side grows with the square root.
    double side = double(scene.terrain.size) * std::sqrt(double(count) / double(natural.size())) * kGrowthMargin;
    const size_t maxSamples =
        std::max(size_t(scene.terrain.resolution) * scene.terrain.resolution, kGrownSamplesPerPlant * count);
    for (int growth = 0; growth < kMaxGrowths; ++growth) {
        Scene grown = scene;
        grown.terrain = grownTerrain(scene.terrain, float(side), maxSamples);
        field.terrain = grown.terrain;
        field.heightfield = terrainOf(grown, memory);
        std::vector<PlantInstance> placed = placeSpecies(field.heightfield, rules, seed, memory);
        if (placed.size() >= count) {
            field.plants = keepCentralSquare(placed, count);
            return field;
        }
        side *= std::sqrt(double(count) / double(std::max<size_t>(placed.size(), 1))) * kGrowthMargin;
    }
    throw SceneError("placement: no terrain grown up to " + std::to_string(int(std::lround(field.terrain.size))) +
                     " m holds " + countText(count) + " at the scene's densities");
}

} // namespace pf
