#include "engine/scene/placement.h"

#include "engine/scene/scene.h"

#include "lsystem/common/random.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace pf {

namespace {

constexpr uint32_t kCandidatesPerPoint = 30;              // Bridson's k
constexpr uint64_t kSamplingSalt = 0x5A3D1E9C40B7F251ull; // keeps the sampling stream apart from the attribute streams
constexpr uint64_t kThinningSalt = 0xC2B2AE3D27D4EB4Full;
constexpr size_t kMaxGridCells = size_t(1) << 28;

// Background grid over the terrain square. With cells of side r/√2 a cell
// holds at most one point of a set with spacing r, so "any point within d"
// looks at a fixed number of cells. Cells hold the point itself (empty cells
// an infinitely far one), so a look-up touches one cache line per cell.
struct PointGrid {
    float origin = 0;
    float cell = 0;
    uint32_t side = 0;
    std::vector<glm::vec2> cells;
    std::vector<glm::vec2> points; // in insertion order

    PointGrid(float terrainSize, float cellSize) : origin(-0.5f * terrainSize), cell(cellSize) {
        const double cellsPerSide = std::ceil(double(terrainSize) / double(cellSize));
        if (cellsPerSide * cellsPerSide > double(kMaxGridCells))
            throw std::invalid_argument("placement: distance " +
                                        std::to_string(cellSize * std::numbers::sqrt2_v<float>) +
                                        " m is too small for a " + std::to_string(terrainSize) + " m terrain");
        side = std::max(1u, uint32_t(cellsPerSide));
        cells.assign(size_t(side) * side, glm::vec2(std::numeric_limits<float>::infinity()));
    }

    int32_t cellIndex(float v) const { return std::clamp(int32_t((v - origin) / cell), 0, int32_t(side) - 1); }

    void insert(glm::vec2 p) {
        cells[size_t(cellIndex(p.y)) * side + size_t(cellIndex(p.x))] = p;
        points.push_back(p);
    }

    bool anyWithin(glm::vec2 p, float distance) const {
        const int32_t reach = int32_t(std::ceil(distance / cell));
        const int32_t cx = cellIndex(p.x), cz = cellIndex(p.y);
        const int32_t x0 = std::max(cx - reach, 0), x1 = std::min(cx + reach, int32_t(side) - 1);
        const float distanceSquared = distance * distance;
        for (int32_t z = std::max(cz - reach, 0); z <= std::min(cz + reach, int32_t(side) - 1); ++z) {
            const glm::vec2* row = &cells[size_t(z) * side];
            for (int32_t x = x0; x <= x1; ++x) {
                const glm::vec2 d = row[x] - p;
                if (d.x * d.x + d.y * d.y < distanceSquared) return true;
            }
        }
        return false;
    }
};

// The plants of a rule sampled earlier, and the distance a later rule's plant
// must keep from them.
struct Neighbour {
    const PointGrid* kept;
    float clearance;
};

void validate(const PlacementRule& rule, size_t index) {
    const std::string where = "placement rule " + std::to_string(index) + ": ";
    const float distance = ruleDistance(rule);
    if (!(distance > 0) || !std::isfinite(distance))
        throw std::invalid_argument(where + "needs a positive density or distance");
    if (!(rule.clearance >= 0)) throw std::invalid_argument(where + "clearance must not be negative");
    if (!(rule.minScale <= rule.maxScale)) throw std::invalid_argument(where + "minScale is above maxScale");
    if (!(rule.minHeight <= rule.maxHeight)) throw std::invalid_argument(where + "minHeight is above maxHeight");
    if (rule.variants == 0) throw std::invalid_argument(where + "needs at least one variant");
}

// Bridson's Poisson-disk sampling of the whole terrain square for one rule.
// Candidates where the rule may not stand (slope, height, clearance of earlier
// rules) become "ghosts": they keep their own spacing and carry the front
// across excluded ground, but never block a kept plant, so kept plants fill
// their region right up to its border. Returns the kept points in sampling order.
PointGrid sampleRule(const Heightfield& terrain, const PlacementRule& rule, std::span<const Neighbour> earlier,
                     uint64_t seed, size_t ruleIndex) {
    const float r = ruleDistance(rule);
    const float half = 0.5f * terrain.size;
    const float minNormalY = std::cos(glm::radians(std::min(rule.maxSlopeDegrees, 90.0f)));
    PointGrid kept(terrain.size, r / std::numbers::sqrt2_v<float>);
    PointGrid ghosts(terrain.size, kept.cell);

    const bool heightLimited =
        rule.minHeight > std::numeric_limits<float>::lowest() || rule.maxHeight < std::numeric_limits<float>::max();
    auto admitted = [&](glm::vec2 p) {
        if (heightLimited) {
            const float h = heightAt(terrain, p.x, p.y);
            if (h < rule.minHeight || h > rule.maxHeight) return false;
        }
        if (rule.maxSlopeDegrees < 90 && normalAt(terrain, p.x, p.y).y < minNormalY) return false;
        return std::none_of(earlier.begin(), earlier.end(), [&](const Neighbour& n) {
            return n.kept->anyWithin(p, std::max(n.clearance, rule.clearance));
        });
    };

    // SplitMix64 is itself counter-based: draw i is mix(key + i·γ). One 64-bit
    // draw gives a candidate's radius and angle, 32 bits each.
    uint64_t sampling = lsys::splitmix64(lsys::splitmix64(seed ^ kSamplingSalt) ^ ruleIndex);
    auto draw = [&] { return lsys::splitmix64(sampling += 0x9E3779B97F4A7C15ull); };
    auto unit = [](uint64_t bits) { return float(bits >> 40) * 0x1.0p-24f; }; // [0, 1) from the top 24 bits
    std::vector<glm::vec2> active;
    auto tryAdd = [&](glm::vec2 p) {
        PointGrid& set = admitted(p) ? kept : ghosts;
        if (set.anyWithin(p, r)) return false;
        set.insert(p);
        active.push_back(p);
        return true;
    };

    const uint64_t start = draw();
    tryAdd({unit(start) * terrain.size - half, unit(start << 32) * terrain.size - half});
    while (!active.empty()) {
        const size_t i = size_t((draw() >> 32) * active.size() >> 32); // uniform in [0, active.size())
        const glm::vec2 centre = active[i];
        bool added = false;
        for (uint32_t k = 0; k < kCandidatesPerPoint && !added; ++k) {
            // Uniform by area in the annulus [r, 2r].
            const uint64_t bits = draw();
            const float radius = r * std::sqrt(1.0f + 3.0f * unit(bits));
            const float angle = 2.0f * std::numbers::pi_v<float> * unit(bits << 32);
            const glm::vec2 p = centre + radius * glm::vec2(std::cos(angle), std::sin(angle));
            added = std::abs(p.x) <= half && std::abs(p.y) <= half && tryAdd(p);
        }
        if (!added) {
            active[i] = active.back();
            active.pop_back();
        }
    }
    return kept;
}

// Whether plants of two rules keep a distance from each other (the larger of
// their clearances): only then does the later rule read the earlier's plants.
bool keepApart(const PlacementRule& a, const PlacementRule& b) { return std::max(a.clearance, b.clearance) > 0; }

// Runs every task, all but the first on threads of their own, and rethrows
// the first failure once all have ended.
void runTogether(const std::vector<std::function<void()>>& tasks) {
    std::vector<std::exception_ptr> failures(tasks.size());
    auto run = [&](size_t i) {
        try {
            tasks[i]();
        } catch (...) {
            failures[i] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    for (size_t i = 1; i < tasks.size(); ++i) threads.emplace_back(run, i);
    if (!tasks.empty()) run(0);
    for (std::thread& thread : threads) thread.join();
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
}

// Uniform in [0, 2π): rounding to float can reach 2π itself, the same angle as 0.
float randomAngle(lsys::RandomStream& random) {
    const float angle = float(random.uniform() * 2.0 * std::numbers::pi);
    return angle < 2.0f * std::numbers::pi_v<float> ? angle : 0.0f;
}

// Per-plant attributes from a counter-based stream of (seed, rule, index), so
// a plant's look never depends on how many others were drawn before it.
PlantInstance makeInstance(const Heightfield& terrain, const PlacementRule& rule, glm::vec2 p, uint64_t seed,
                           size_t ruleIndex, size_t index) {
    lsys::RandomStream random = lsys::RandomStream::forModule(seed, ruleIndex, index);
    PlantInstance instance;
    instance.position = {p.x, heightAt(terrain, p.x, p.y), p.y};
    instance.rotation = randomAngle(random);
    instance.scale = std::lerp(rule.minScale, rule.maxScale, float(random.uniform()));
    instance.species = rule.species;
    instance.variant = std::min(uint32_t(random.uniform() * rule.variants), rule.variants - 1);
    instance.windPhase = randomAngle(random);
    return instance;
}

// The `count` plants of `placed` with the smallest keys (ties by position),
// back in placement order, which is spatially coherent.
template <typename Key>
std::vector<PlantInstance> keepSmallest(const std::vector<PlantInstance>& placed, size_t count, Key keyOf) {
    using Keyed = std::pair<decltype(keyOf(placed[0], uint32_t(0))), uint32_t>;
    std::vector<Keyed> order(placed.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = {keyOf(placed[i], i), i};
    count = std::min(count, placed.size());
    std::nth_element(order.begin(), order.begin() + ptrdiff_t(count), order.end());
    order.resize(count);
    std::sort(order.begin(), order.end(), [](const Keyed& a, const Keyed& b) { return a.second < b.second; });
    std::vector<PlantInstance> kept;
    kept.reserve(count);
    for (const Keyed& entry : order) kept.push_back(placed[entry.second]);
    return kept;
}

std::vector<PlantInstance> thinToCount(const std::vector<PlantInstance>& placed, size_t count, uint64_t seed) {
    const uint64_t key = lsys::splitmix64(seed ^ kThinningSalt);
    return keepSmallest(placed, count, [&](const PlantInstance&, uint32_t i) { return lsys::splitmix64(key ^ i); });
}

// About how many plants a rule with distance r places on open flat ground.
float unlimitedCount(const Heightfield& terrain, float r) {
    return terrain.size * terrain.size * kPoissonPackingFactor * kPoissonPackingFactor / (r * r);
}

} // namespace

float poissonDistanceForDensity(float plantsPerHectare) {
    return std::sqrt(10000.0f / plantsPerHectare) * kPoissonPackingFactor;
}

float ruleDistance(const PlacementRule& rule) {
    return rule.densityPerHectare > 0 ? poissonDistanceForDensity(rule.densityPerHectare) : rule.minDistance;
}

std::vector<PlantInstance> placePoissonDisk(const Heightfield& terrain, const PlacementRule& rule, uint64_t seed) {
    return placeSpecies(terrain, std::span(&rule, 1), seed);
}

uint64_t placementSamplingBytes(const Heightfield& terrain, std::span<const PlacementRule> rules) {
    uint64_t bytes = 0;
    for (const PlacementRule& rule : rules) {
        const double r = ruleDistance(rule);
        const double cellsPerSide = std::ceil(double(terrain.size) * std::numbers::sqrt2 / r);
        const double plants = double(unlimitedCount(terrain, float(r)));
        // Kept and ghost grids; each plant in a grid's list, the active list and as an instance.
        const double ruleBytes = cellsPerSide * cellsPerSide * 2.0 * sizeof(glm::vec2) +
                                 plants * (3.0 * sizeof(glm::vec2) + sizeof(PlantInstance));
        bytes = lsys::bytesPlus(bytes, ruleBytes < 0x1p64 ? uint64_t(ruleBytes) : UINT64_MAX);
    }
    return bytes;
}

std::vector<PlantInstance> placeSpecies(const Heightfield& terrain, std::span<const PlacementRule> rules, uint64_t seed,
                                        const lsys::MemoryBudget& memory) {
    for (size_t i = 0; i < rules.size(); ++i) validate(rules[i], i);
    lsys::need(memory, "placement", placementSamplingBytes(terrain, rules));
    // Large plants claim their ground first; ties keep the order of `rules`.
    std::vector<size_t> sampling(rules.size());
    for (size_t i = 0; i < rules.size(); ++i) sampling[i] = i;
    std::stable_sort(sampling.begin(), sampling.end(),
                     [&](size_t a, size_t b) { return ruleDistance(rules[a]) > ruleDistance(rules[b]); });

    // A rule reads the kept plants of the earlier rules it keeps a clearance
    // from, so it waits for them; rules that keep none from each other are
    // sampled together, each on its own thread. Each sampling is
    // single-threaded with its own streams, so the field does not depend on
    // how many run at once.
    std::vector<size_t> wave(rules.size(), 0);
    for (size_t j = 0; j < sampling.size(); ++j)
        for (size_t i = 0; i < j; ++i)
            if (keepApart(rules[sampling[i]], rules[sampling[j]]))
                wave[sampling[j]] = std::max(wave[sampling[j]], wave[sampling[i]] + 1);
    std::vector<std::optional<PointGrid>> kept(rules.size());
    for (size_t w = 0; std::find(wave.begin(), wave.end(), w) != wave.end(); ++w) {
        std::vector<std::function<void()>> tasks;
        for (size_t j = 0; j < sampling.size(); ++j) {
            const size_t ruleIndex = sampling[j];
            if (wave[ruleIndex] != w) continue;
            std::vector<Neighbour> earlier;
            for (size_t i = 0; i < j; ++i)
                if (keepApart(rules[sampling[i]], rules[ruleIndex]))
                    earlier.push_back({&*kept[sampling[i]], rules[sampling[i]].clearance});
            tasks.push_back([&, ruleIndex, earlier = std::move(earlier)] {
                kept[ruleIndex].emplace(
                    sampleRule(terrain, rules[ruleIndex], earlier, seed ^ rules[ruleIndex].seed, ruleIndex));
            });
        }
        runTogether(tasks);
    }

    // Grouped by rule in the order of `rules`; each rule's plants made on a thread of their own.
    std::vector<size_t> first(rules.size() + 1, 0);
    for (size_t ruleIndex = 0; ruleIndex < rules.size(); ++ruleIndex)
        first[ruleIndex + 1] = first[ruleIndex] + kept[ruleIndex]->points.size();
    std::vector<PlantInstance> instances(first.back());
    std::vector<std::function<void()>> tasks;
    for (size_t ruleIndex = 0; ruleIndex < rules.size(); ++ruleIndex)
        tasks.push_back([&, ruleIndex] {
            const std::vector<glm::vec2>& points = kept[ruleIndex]->points;
            for (size_t i = 0; i < points.size(); ++i)
                instances[first[ruleIndex] + i] =
                    makeInstance(terrain, rules[ruleIndex], points[i], seed ^ rules[ruleIndex].seed, ruleIndex, i);
        });
    runTogether(tasks);
    return instances;
}

std::vector<PlantInstance> scaleToCount(const Heightfield& terrain, std::span<const PlacementRule> rules, size_t count,
                                        uint64_t seed) {
    if (count == 0) return {};
    // The same rules with every distance and clearance times `scale`: a
    // similar field, with about 1/scale² as many plants.
    auto placeScaled = [&](float scale) {
        std::vector<PlacementRule> scaled(rules.begin(), rules.end());
        for (PlacementRule& rule : scaled) {
            rule.minDistance = ruleDistance(rule) * scale;
            rule.densityPerHectare = 0;
            rule.clearance *= scale;
        }
        return placeSpecies(terrain, scaled, seed);
    };
    // A cheap pilot of about kPilotPlants plants (when the rules would give
    // more) measures how much the terrain limits and clearances remove.
    constexpr float kPilotPlants = 20000;
    float unlimited = 0; // plants on open flat ground
    for (const PlacementRule& rule : rules) unlimited += unlimitedCount(terrain, ruleDistance(rule));
    float scale = std::max(1.0f, std::sqrt(unlimited / kPilotPlants));
    std::vector<PlantInstance> placed = placeScaled(scale);
    for (bool pilot = true; pilot || placed.size() < count; pilot = false) {
        if (placed.empty())
            throw SceneError("placement: the rules admit no plant on this terrain"); // the scene's fault: exit 2
        // 2 % more than needed, so one placement after the pilot nearly always suffices.
        scale *= std::sqrt(float(placed.size()) / float(count)) * 0.99f;
        placed = placeScaled(scale);
    }
    return thinToCount(placed, count, seed);
}

std::vector<PlantInstance> keepCentralSquare(const std::vector<PlantInstance>& plants, size_t count) {
    return keepSmallest(plants, count, [](const PlantInstance& p, uint32_t) {
        return std::max(std::abs(p.position.x), std::abs(p.position.z));
    });
}

} // namespace pf
