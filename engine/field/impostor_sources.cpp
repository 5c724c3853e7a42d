#include "engine/field/impostor_sources.h"

#include "engine/scene/scene.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace pf {
namespace {

// The species' name: a model's name is "<species name>#<variant>".
std::string speciesName(const PlantModelPool& pool, size_t species) {
    const std::string& name = pool.models[pool.firstModel[species]].name;
    return name.substr(0, name.rfind('#'));
}

} // namespace

std::vector<uint32_t> impostorSources(const PlantModelPool& pool, uint32_t modelCapacity) {
    const size_t models = pool.models.size(), species = pool.firstModel.size();
    std::vector<uint32_t> sources(models);
    std::iota(sources.begin(), sources.end(), 0u);
    if (models <= modelCapacity) return sources;
    if (species > modelCapacity)
        throw SceneError("the impostor atlas holds the frames of at most " + std::to_string(modelCapacity) +
                         " plant models on this device (its image array layers), one a species at least: species \"" +
                         speciesName(pool, modelCapacity) + "\" (of " + std::to_string(species) +
                         ") gets none; give the scene fewer species");
    std::vector<uint32_t> variants(species), kept(species);
    for (size_t s = 0; s < species; ++s) {
        const size_t end = s + 1 < species ? pool.firstModel[s + 1] : models;
        variants[s] = uint32_t(end - pool.firstModel[s]);
        kept[s] = std::max<uint32_t>(1, uint32_t(uint64_t(variants[s]) * modelCapacity / models));
    }
    // max(1, …) may round the sum past the capacity: the largest give way.
    while (std::accumulate(kept.begin(), kept.end(), uint64_t{0}) > modelCapacity)
        --*std::max_element(kept.begin(), kept.end());
    for (size_t s = 0; s < species; ++s)
        for (uint32_t v = 0; v < variants[s]; ++v) sources[pool.firstModel[s] + v] = pool.firstModel[s] + v % kept[s];
    return sources;
}

} // namespace pf
