#include "lsystem/turtle/turtle.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace lsys {

TurtleSettings turtleSettings(const Grammar& grammar) {
    TurtleSettings settings;
    settings.angle = static_cast<float>(grammar.angle);
    settings.step = static_cast<float>(grammar.step);
    settings.width = static_cast<float>(grammar.width);
    const TurtleStyle& style = grammar.style;
    settings.widthFactor = static_cast<float>(style.widthFactor);
    settings.widthIncrement = static_cast<float>(style.widthIncrement);
    settings.colorIncrement = style.colorIncrement;
    settings.material = style.material;
    settings.tropism = style.tropism;
    settings.elasticity = static_cast<float>(style.elasticity);
    settings.pixelLines = style.pixelLines;
    settings.cpfgModules = style.cpfgModules;
    settings.movements = style.movements;
    settings.look = style.look;
    return settings;
}

TurtleState initialTurtleState(const TurtleSettings& settings) {
    TurtleState state;
    state.width = settings.width;
    state.length = settings.step;
    state.angle = settings.angle;
    state.tropism = settings.tropism;
    state.elasticity = settings.elasticity;
    state.material = settings.material;
    for (size_t i = 0; i < settings.movements.size() && i < kMaxMovements; ++i)
        state.movementElasticity[i] = settings.movements[i].elasticity;
    return state;
}

Frame frameOf(const TurtleState& s) {
    // Columns are the images of local +X, +Y, +Z: -L, H, U.
    return {s.position, glm::normalize(glm::quat_cast(glm::mat3(-s.left, s.heading, s.up)))};
}

void applyModule(const TurtleCommand& command, std::span<const float> parameters, const TurtleSettings& settings,
                 TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out) {
    const TurtleCommandDefinition& definition = actingDefinition(command.action, stack.polygons.size());
    // NaN or infinity would spread through every frame after it into the
    // meshes and exports (glTF forbids them): stop at the module that brings it.
    if (command.action != TurtleAction::None)
        for (float value : parameters)
            if (!std::isfinite(value))
                throw DerivationError("the turtle's " + std::string(definition.symbol) + " got " +
                                      (std::isnan(value) ? "NaN" : "an infinite value") +
                                      " as a parameter (an expression divides by zero or leaves its domain)");
    definition.apply({command, parameters, settings, state, stack, out});
    // Finite steps can still add up past the float range (F(3e38) twice).
    if (!std::isfinite(state.position.x) || !std::isfinite(state.position.y) || !std::isfinite(state.position.z))
        throw DerivationError("the turtle's " + std::string(definition.symbol) +
                              " moved it past the float range: its position is no longer a finite number");
}

void interpretModules(const ModuleString& string, std::span<const TurtleCommand> commands,
                      const TurtleSettings& settings, TurtleState& state, TurtleStack& stack, PlantAssetBuilder& out) {
    for (size_t i = 0; i < string.size(); ++i) {
        const TurtleCommand& command = commands[string.symbols[i]];
        if (command.action == TurtleAction::Cut)
            i = endOfBranch(string, i + 1) - 1;
        else
            applyModule(command, string.parameters(i), settings, state, stack, out);
    }
}

uint64_t turtleBytes(const ModuleString& string, std::span<const TurtleCommand> commands) {
    std::vector<uint64_t> perSymbol(commands.size(), 0);
    for (size_t symbol = 0; symbol < commands.size(); ++symbol) {
        switch (commands[symbol].action) {
        case TurtleAction::Draw:
        case TurtleAction::DrawWithoutVertex: perSymbol[symbol] = sizeof(Primitive) + sizeof(Joint); break;
        case TurtleAction::Sphere:
        case TurtleAction::Surface: perSymbol[symbol] = sizeof(Primitive); break;
        case TurtleAction::PolygonBegin:
            perSymbol[symbol] = sizeof(Primitive) + sizeof(PolygonShape) + sizeof(OpenPolygon);
            break;
        case TurtleAction::PolygonVertex:
        case TurtleAction::Move:
        case TurtleAction::MoveWithoutVertex: perSymbol[symbol] = sizeof(glm::vec3); break;
        case TurtleAction::Push: perSymbol[symbol] = sizeof(TurtleState); break;
        default: break;
        }
    }
    uint64_t bytes = 0;
    for (SymbolId symbol : string.symbols) bytes += perSymbol[symbol]; // at most 2^32 x a few hundred bytes
    return bytesTimes(bytes, 2);
}

PlantAsset interpretPlant(const ModuleString& string, const SymbolTable& symbols, const TurtleSettings& settings,
                          const SurfaceLibrary& surfaces, const MemoryBudget& memory) {
    const std::vector<TurtleCommand> commands = turtleCommands(symbols, settings.cpfgModules);
    need(memory, "turtle", turtleBytes(string, commands));
    PlantAssetBuilder builder(surfaces, settings.look);
    TurtleState state = initialTurtleState(settings);
    TurtleStack stack;
    interpretModules(string, commands, settings, state, stack, builder);
    PlantAsset plant = builder.finish();
    if (settings.pixelLines) widenPixelLines(plant);
    return plant;
}

float worldPerPixel(const Bounds& bounds) {
    if (bounds.empty()) return 0.0f;
    const glm::vec3 extent = bounds.max - bounds.min;
    return std::max(extent.x, extent.y) / kPixelsAcrossPlant;
}

float scaleLineRadii(PlantAsset& plant, float factor) {
    float widest = 0.0f;
    for (Primitive& primitive : plant.primitives) {
        if (primitive.kind != PrimitiveKind::Segment) continue;
        primitive.startRadius *= factor;
        primitive.endRadius *= factor;
        widest = std::max({widest, primitive.startRadius, primitive.endRadius});
    }
    for (Joint& joint : plant.joints) {
        joint.startRadius *= factor;
        joint.endRadius *= factor;
    }
    return widest;
}

void widenPixelLines(PlantAsset& plant) {
    if (plant.bounds.empty()) return;
    const float widest = scaleLineRadii(plant, worldPerPixel(plant.bounds));
    plant.bounds.min -= glm::vec3(widest);
    plant.bounds.max += glm::vec3(widest);
}

} // namespace lsys
