#include "engine/scene/cloud_spheres.h"

#include "lsystem/common/error.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

#include <algorithm>
#include <limits>
#include <string>

namespace pf {
namespace {

// Far more modules than kMaxCloudSpheres spheres need: a grammar that runs
// away stops here with a message instead of filling memory.
constexpr size_t kCloudModuleBudget = 1'000'000;

lsys::PlantAsset cloudPlant(const std::filesystem::path& file, std::optional<uint32_t> seed) {
    lsys::vlab::PlantFile plant = lsys::vlab::loadPlant(file);
    if (!plant.parsed.ok()) throw CloudError(lsys::formatDiagnostics(plant.parsed.diagnostics, plant.source));
    const lsys::Grammar& grammar = plant.parsed.grammar;
    lsys::DeriveOptions options;
    if (seed) options.seed = *seed;
    options.maxModules = kCloudModuleBudget;
    try {
        return lsys::plantFromGrammar(grammar, lsys::derive(grammar, options));
    } catch (const lsys::ModuleBudgetError& error) {
        throw CloudError(std::string(error.what()) + "; give the cloud fewer derivation steps");
    } catch (const std::runtime_error& error) { // DerivationError, MemoryBudgetError: the file's own fault
        throw CloudError(error.what());
    }
}

} // namespace

std::vector<CloudSphere> cloudSpheres(const std::filesystem::path& file, std::optional<uint32_t> seed, float size,
                                      const glm::vec3& base) {
    const lsys::PlantAsset plant = cloudPlant(file, seed);
    std::vector<CloudSphere> spheres;
    glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    float lowestCentre = std::numeric_limits<float>::max(), highestCentre = std::numeric_limits<float>::lowest();
    for (const lsys::Primitive& primitive : plant.primitives) {
        if (primitive.kind != lsys::PrimitiveKind::Sphere || !(primitive.startRadius > 0.0f)) continue;
        if (spheres.size() == kMaxCloudSpheres)
            throw CloudError("draws more than " + std::to_string(kMaxCloudSpheres) +
                             " spheres, the most a cloud may have; give it fewer derivation steps");
        const glm::vec3 centre = primitive.frame.position;
        spheres.push_back({centre, primitive.startRadius, 0.0f});
        low = glm::min(low, centre - primitive.startRadius);
        high = glm::max(high, centre + primitive.startRadius);
        lowestCentre = std::min(lowestCentre, centre.y);
        highestCentre = std::max(highestCentre, centre.y);
    }
    if (spheres.empty()) throw CloudError("draws no sphere: a cloud is the spheres its L-system draws with @O(d)");

    const glm::vec3 extent = high - low;
    const float scale = size / std::max({extent.x, extent.y, extent.z});
    const glm::vec3 bottomMiddle(0.5f * (low.x + high.x), low.y, 0.5f * (low.z + high.z));
    const float centreSpan = highestCentre - lowestCentre;
    const glm::vec3 middle = 0.5f * (low + high), halfExtent = 0.5f * extent;
    for (CloudSphere& sphere : spheres) {
        sphere.height = centreSpan > 0.0f ? (sphere.centre.y - lowestCentre) / centreSpan : 0.5f;
        // The ellipsoid x²/a² + y²/b² + z²/c² = k through the centre has the normal (x/a², y/b², z/c²).
        const glm::vec3 normal = (sphere.centre - middle) / (halfExtent * halfExtent);
        if (glm::dot(normal, normal) > 0.0f) sphere.outward = glm::normalize(normal);
        sphere.centre = base + (sphere.centre - bottomMiddle) * scale;
        sphere.radius *= scale;
    }
    return spheres;
}

} // namespace pf
