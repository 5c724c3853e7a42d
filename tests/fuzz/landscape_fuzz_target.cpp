// The L-systems of a scene's landscape: terrain L-systems that leave
// mountains (lsystem/landscape) and cloud L-systems whose spheres make a
// cloud (engine/scene/cloud_spheres).
#include "fuzz_targets.h"
#include "input_file.h"

#include "engine/scene/cloud_spheres.h"
#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/dialects/dialect.h"
#include "lsystem/landscape/mountain_turtle.h"
#include "lsystem/landscape/terrain_bumps.h"

#include <string_view>
#include <vector>

namespace pf::fuzz {

void runTerrainInput(const uint8_t* data, size_t size) {
    const lsys::ParseResult parsed =
        lsys::parseDialect(std::nullopt, std::string_view(reinterpret_cast<const char*>(data), size));
    if (!parsed.ok()) return;
    try {
        const lsys::MemoryBudget memory{256ull << 20};
        const std::vector<lsys::landscape::TerrainBump> bumps =
            lsys::landscape::mountainBumpsOf(parsed.grammar, lsys::landscape::MountainPlacement{}, 7u, memory);
        // The bumps on a small terrain, as the scene's height field takes them.
        constexpr uint32_t kResolution = 33;
        std::vector<float> heights(size_t(kResolution) * kResolution, 0.0f);
        if (lsys::landscape::bumpSamples(kResolution, 2000.0f, bumps) <= lsys::landscape::kMaxBumpSamples)
            lsys::landscape::addBumps(heights, kResolution, 2000.0f, bumps);
    } catch (const lsys::DerivationError&) {
        // Past the module budget, a bump past max_height, too many bumps: a clear error.
    } catch (const lsys::MemoryBudgetError&) {
        // The turtle or the derivation refused for the memory it would take.
    }
}

void runCloudInput(const uint8_t* data, size_t size) {
    try {
        (void)cloudSpheres(writeInputFile(data, size, "clouds/input.lsys"), 3u, 400.0f, glm::vec3(0.0f, 900.0f, 0.0f));
    } catch (const CloudError&) {
        // A malformed file, a runaway derivation, no sphere or too many: a clear error.
    }
}

} // namespace pf::fuzz
