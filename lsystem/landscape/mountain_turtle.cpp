#include "lsystem/landscape/mountain_turtle.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle_builder.h"
#include "lsystem/turtle/turtle_commands.h"

namespace lsys::landscape {

namespace {

constexpr std::array kMountainShapes{BumpShape::Hill, BumpShape::Peak, BumpShape::Mesa, BumpShape::Valley};

// The turtle lying on the ground at the origin, heading turned about +y.
TurtleState groundTurtle(const TurtleSettings& settings, float headingDegrees) {
    TurtleState state = initialTurtleState(settings);
    const float angle = headingDegrees * std::numbers::pi_v<float> / 180.0f;
    state.heading = {std::cos(angle), 0.0f, -std::sin(angle)};
    state.up = {0.0f, 1.0f, 0.0f};
    state.left = glm::cross(state.up, state.heading); // H × L = U
    state.segmentHeading = state.heading;
    state.segmentUp = state.up;
    return state;
}

std::string metres(float value) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << value << " m";
    return text.str();
}

// "Peak (module 57 of the derived word)"
std::string moduleText(BumpShape shape, size_t module) {
    return std::string(bumpShapeName(shape)) + " (module " + std::to_string(module) + " of the derived word)";
}

// "Peak (module 57 of the derived word) at x 120.0 m, z -40.0 m"
std::string describeBump(const TerrainBump& bump, size_t module) {
    return moduleText(bump.shape, module) + " at x " + metres(bump.x) + ", z " + metres(bump.z);
}

TerrainBump bumpOf(BumpShape shape, std::span<const float> parameters, const TurtleState& turtle,
                   const MountainPlacement& placement, size_t module) {
    if (parameters.size() > 2)
        throw MountainError(moduleText(shape, module) +
                            " takes at most 2 parameters, a height factor and a radius factor, not " +
                            std::to_string(parameters.size()));
    for (float value : parameters)
        if (!std::isfinite(value))
            throw MountainError(moduleText(shape, module) + " got a parameter that is not a finite number");
    const float heightFactor = parameters.size() > 0 ? parameters[0] : 1.0f;
    const float radiusFactor = parameters.size() > 1 ? parameters[1] : 1.0f;
    TerrainBump bump;
    bump.shape = shape;
    bump.x = placement.originX + placement.scale * turtle.position.x;
    bump.z = placement.originZ + placement.scale * turtle.position.z;
    bump.height = placement.scale * turtle.position.y * heightFactor * (shape == BumpShape::Valley ? -1.0f : 1.0f);
    bump.radius = 0.5f * turtle.width * placement.scale * radiusFactor; // widths are diameters
    if (!std::isfinite(bump.x) || !std::isfinite(bump.z) || !std::isfinite(bump.height) || !std::isfinite(bump.radius))
        throw MountainError(moduleText(shape, module) + " lies too far or too high for a float: its turtle is at (" +
                            std::to_string(turtle.position.x) + ", " + std::to_string(turtle.position.y) + ", " +
                            std::to_string(turtle.position.z) + ") with width " + std::to_string(turtle.width) +
                            ", times the scale");
    if (!(bump.radius > 0.0f))
        throw MountainError(describeBump(bump, module) +
                            " has no width: its radius, half the turtle's width (!) times its radius factor and the "
                            "scale, must be > 0");
    return bump;
}

// The chapter's warning (§22): a turtle straying far above or below its
// start makes extreme peaks. The sum is checked at the bumps' centres, where
// the summits and pits of superimposed bumps lie; between centres
// overlapping flanks can add up a little higher.
void checkPeaks(const std::vector<TerrainBump>& bumps, const std::vector<size_t>& modules,
                const MountainPlacement& placement) {
    for (size_t i = 0; i < bumps.size(); ++i) {
        const float sum = bumpsHeightAt(bumps, bumps[i].x, bumps[i].z);
        if (!(std::abs(sum) <= placement.maxHeight)) // NaN too
            throw MountainError(describeBump(bumps[i], modules[i]) + " makes the ground " + metres(std::abs(sum)) +
                                (sum > 0 ? " high" : " deep") + " there with the bumps around it, past max_height " +
                                metres(placement.maxHeight) +
                                ": keep the turtle's branches within a few steps of its horizontal core, or raise "
                                "max_height");
    }
}

} // namespace

std::vector<TerrainBump> mountainBumps(const ModuleString& word, const SymbolTable& symbols,
                                       const TurtleSettings& settings, const MountainPlacement& placement,
                                       const MemoryBudget& memory) {
    std::vector<std::optional<BumpShape>> shapeOf(symbols.size());
    for (BumpShape shape : kMountainShapes)
        if (const std::optional<SymbolId> id = symbols.find(bumpShapeName(shape))) shapeOf[*id] = shape;
    const std::vector<TurtleCommand> commands = turtleCommands(symbols, settings.cpfgModules);
    need(memory, "turtle", turtleBytes(word, commands));
    const SurfaceLibrary noSurfaces;
    PlantAssetBuilder ignored(noSurfaces, settings.look); // the segments a plant would draw
    TurtleState state = groundTurtle(settings, placement.headingDegrees);
    TurtleStack stack;
    std::vector<TerrainBump> bumps;
    std::vector<size_t> modules; // of each bump, for its messages
    for (size_t i = 0; i < word.size(); ++i) {
        const SymbolId symbol = word.symbols[i];
        if (const std::optional<BumpShape> shape = shapeOf[symbol]) {
            if (bumps.size() == placement.maxBumps)
                throw MountainError("the mountain word makes more than " + std::to_string(placement.maxBumps) +
                                    " bumps (module " + std::to_string(i) +
                                    " is one too many): derive it fewer steps or give it fewer mountain modules");
            bumps.push_back(bumpOf(*shape, word.parameters(i), state, placement, i));
            modules.push_back(i);
        } else if (commands[symbol].action == TurtleAction::Cut) {
            i = endOfBranch(word, i + 1) - 1;
        } else {
            try {
                applyModule(commands[symbol], word.parameters(i), settings, state, stack, ignored);
            } catch (const SurfaceError& error) { // a mountain word has no meshes beside it
                throw MountainError("module " + std::to_string(i) + " of the mountain word: " + error.what());
            }
        }
    }
    checkPeaks(bumps, modules, placement);
    return bumps;
}

std::vector<TerrainBump> mountainBumpsOf(const Grammar& grammar, const MountainPlacement& placement,
                                         std::optional<uint64_t> seed, const MemoryBudget& memory) {
    DeriveOptions options;
    options.seed = seed;
    options.maxModules = kMaxMountainModules;
    options.memory = memory;
    ModuleString word = derive(grammar, options);
    if (!grammar.interpretation.empty()) word = applyInterpretation(grammar, word, options);
    return mountainBumps(word, grammar.symbols, turtleSettings(grammar), placement, memory);
}

} // namespace lsys::landscape
