#include "lsystem/turtle.h"

#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "lsystem/rewriter.h"

namespace lsys {

namespace {

// Rotates the two frame vectors other than axis by degrees about axis, then
// re-orthonormalises so rounding does not accumulate.
void rotate(TurtleState& s, glm::vec3 axis, float degrees) {
    const glm::quat rotation = glm::angleAxis(glm::radians(degrees), axis);
    s.heading = glm::normalize(rotation * s.heading);
    const glm::vec3 left = rotation * s.left;
    s.left = glm::normalize(left - glm::dot(left, s.heading) * s.heading);
    s.up = glm::cross(s.heading, s.left);
}

// ABOP's $: L = V x H / |V x H| with V the world up (+Y).
void rollHorizontal(TurtleState& s) {
    const glm::vec3 horizontalLeft = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), s.heading);
    if (glm::length(horizontalLeft) < 1e-6f) return; // heading vertical: any roll is horizontal
    s.left = glm::normalize(horizontalLeft);
    s.up = glm::cross(s.heading, s.left);
}

// ABOP §2.4: after a segment, H turns toward T by e * |H x T| about H x T.
void bendTowardTropism(TurtleState& s) {
    if (s.elasticity == 0.0f) return;
    const glm::vec3 axis = glm::cross(s.heading, s.tropism);
    const float sine = glm::length(axis);
    if (!(sine > 1e-6f)) return; // parallel to T (or NaN): no defined bend
    rotate(s, axis / sine, glm::degrees(s.elasticity * sine));
}

// cpfg's colour map has 256 entries; parameters are arbitrary floats, and
// negative, huge or NaN indices become 0.
uint32_t materialIndex(float value) { return value >= 0.0f && value < 256.0f ? static_cast<uint32_t>(value) : 0; }

// A segment drawn backwards (negative length) faces the other way.
Frame segmentFrame(const TurtleState& s, float length) {
    Frame frame = frameOf(s);
    if (length < 0.0f) frame.rotation = frame.rotation * glm::angleAxis(glm::radians(180.0f), glm::vec3(0, 0, 1));
    return frame;
}

// A vertex of the innermost open polygon, if there is one.
void addVertex(TurtleStack& stack, glm::vec3 position) {
    if (!stack.polygons.empty()) stack.polygons.back().outline.push_back(position);
}

// Moves along H; inside a polygon the new position is one of its vertices.
void move(TurtleState& s, TurtleStack& stack, float length) {
    s.position += s.heading * length;
    addVertex(stack, s.position);
}

void closePolygon(TurtleStack& stack, PlantAssetBuilder& out) {
    if (stack.polygons.empty()) return;
    OpenPolygon polygon = std::move(stack.polygons.back());
    stack.polygons.pop_back();
    std::vector<glm::vec3> outline;
    for (const glm::vec3& p : polygon.outline)
        if (outline.empty() || glm::distance(p, outline.back()) > 1e-6f) outline.push_back(p);
    if (outline.size() > 1 && glm::distance(outline.front(), outline.back()) <= 1e-6f) outline.pop_back();
    if (outline.size() >= 3) out.addPolygon(polygon.start, std::move(outline), polygon.material, polygon.joint);
}

void drawSegment(std::span<const float> p, TurtleState& s, TurtleStack& stack, PlantAssetBuilder& out) {
    const float length = p.empty() ? s.length : p[0];
    if (!stack.polygons.empty()) {
        move(s, stack, length); // a polygon's outline, not a branch
        return;
    }
    const float startWidth = s.width;
    if (p.size() > 1) s.width = p[1];
    s.joint = out.addSegment(segmentFrame(s, length), std::abs(length), startWidth * 0.5f, s.width * 0.5f, s.material,
                             s.joint, s.stiffness);
    s.position += s.heading * length;
    bendTowardTropism(s);
}

// Index of the ']' closing the branch that contains position i (or the end).
size_t endOfBranch(const ModuleString& string, size_t i) {
    int depth = 0;
    for (; i < string.size(); ++i) {
        if (string.symbols[i] == kPush) ++depth;
        if (string.symbols[i] == kPop && depth-- == 0) return i;
    }
    return i;
}

} // namespace

TurtleSettings turtleSettings(const Grammar& grammar) {
    TurtleSettings settings;
    settings.angle = static_cast<float>(grammar.angle);
    settings.step = static_cast<float>(grammar.step);
    settings.width = static_cast<float>(grammar.width);
    return settings;
}

TurtleState initialTurtleState(const TurtleSettings& settings) {
    TurtleState state;
    state.width = settings.width;
    state.length = settings.step;
    state.angle = settings.angle;
    state.tropism = settings.tropism;
    state.elasticity = settings.elasticity;
    return state;
}

Frame frameOf(const TurtleState& s) {
    // Columns are the images of local +X, +Y, +Z: -L, H, U.
    return {s.position, glm::normalize(glm::quat_cast(glm::mat3(-s.left, s.heading, s.up)))};
}

TurtleCommand turtleCommand(const std::string& name) {
    static const std::unordered_map<std::string, TurtleAction> actions = {
        {"F", TurtleAction::Draw},          {"f", TurtleAction::Move},
        {"+", TurtleAction::Yaw},           {"-", TurtleAction::YawBack},
        {"&", TurtleAction::Pitch},         {"^", TurtleAction::PitchBack},
        {"\\", TurtleAction::Roll},         {"/", TurtleAction::RollBack},
        {"|", TurtleAction::TurnAround},    {"$", TurtleAction::RollHorizontal},
        {"[", TurtleAction::Push},          {"]", TurtleAction::Pop},
        {"!", TurtleAction::Width},         {";", TurtleAction::Material},
        {"'", TurtleAction::Material},      {"%", TurtleAction::Cut},
        {"@Lm", TurtleAction::ScaleLength}, {"@La", TurtleAction::AddLength},
        {"@Ls", TurtleAction::SetLength},   {"@Am", TurtleAction::ScaleAngle},
        {"@Aa", TurtleAction::AddAngle},    {"@As", TurtleAction::SetAngle},
        {"@Wm", TurtleAction::ScaleWidth},  {"@Wa", TurtleAction::AddWidth},
        {"@Ca", TurtleAction::AddMaterial}, {"@K", TurtleAction::Stiffness},
        {"@Ts", TurtleAction::Elasticity},  {"@Tv", TurtleAction::TropismVector},
        {"@O", TurtleAction::Sphere},       {"{", TurtleAction::PolygonBegin},
        {".", TurtleAction::PolygonVertex}, {"}", TurtleAction::PolygonEnd},
    };
    if (name.size() > 1 && name[0] == '~') return {TurtleAction::Surface, name.substr(1)};
    const auto found = actions.find(name);
    return {found == actions.end() ? TurtleAction::None : found->second, {}};
}

std::vector<TurtleCommand> turtleCommands(const SymbolTable& symbols) {
    std::vector<TurtleCommand> commands;
    commands.reserve(symbols.size());
    for (const std::string& name : symbols.names) commands.push_back(turtleCommand(name));
    return commands;
}

void applyModule(const TurtleCommand& command, std::span<const float> p, const TurtleSettings& settings, TurtleState& s,
                 TurtleStack& stack, PlantAssetBuilder& out) {
    const float angle = p.empty() ? s.angle : p[0];
    // Of the length, angle, width and material modules: bare ones change nothing.
    const float factor = p.empty() ? 1.0f : p[0];
    const float amount = p.empty() ? 0.0f : p[0];
    switch (command.action) {
    case TurtleAction::None:
    case TurtleAction::Cut: break; // interpretModules skips the branch
    case TurtleAction::Draw: drawSegment(p, s, stack, out); break;
    case TurtleAction::Move: move(s, stack, p.empty() ? s.length : p[0]); break;
    case TurtleAction::Yaw: rotate(s, s.up, angle); break;
    case TurtleAction::YawBack: rotate(s, s.up, -angle); break;
    case TurtleAction::Pitch: rotate(s, s.left, angle); break;
    case TurtleAction::PitchBack: rotate(s, s.left, -angle); break;
    case TurtleAction::Roll: rotate(s, s.heading, angle); break;
    case TurtleAction::RollBack: rotate(s, s.heading, -angle); break;
    case TurtleAction::TurnAround: rotate(s, s.up, 180.0f); break;
    case TurtleAction::RollHorizontal: rollHorizontal(s); break;
    case TurtleAction::Push: stack.branches.push_back(s); break;
    case TurtleAction::Pop:
        if (!stack.branches.empty()) {
            s = stack.branches.back();
            stack.branches.pop_back();
        }
        break;
    case TurtleAction::Width: s.width = p.empty() ? s.width * settings.widthFactor : p[0]; break;
    case TurtleAction::Material:
        s.material = materialIndex(p.empty() ? static_cast<float>(s.material) + 1.0f : p[0]);
        break;
    case TurtleAction::ScaleLength: s.length *= factor; break;
    case TurtleAction::AddLength: s.length += amount; break;
    case TurtleAction::SetLength:
        if (!p.empty()) s.length = p[0];
        break;
    case TurtleAction::ScaleAngle: s.angle *= factor; break;
    case TurtleAction::AddAngle: s.angle += amount; break;
    case TurtleAction::SetAngle:
        if (!p.empty()) s.angle = p[0];
        break;
    case TurtleAction::ScaleWidth: s.width *= factor; break;
    case TurtleAction::AddWidth: s.width += amount; break;
    case TurtleAction::AddMaterial: s.material = materialIndex(static_cast<float>(s.material) + amount); break;
    case TurtleAction::Stiffness:
        if (!p.empty()) s.stiffness = p[0];
        break;
    case TurtleAction::Elasticity:
        if (!p.empty()) s.elasticity = p[0];
        break;
    case TurtleAction::TropismVector:
        if (p.size() >= 3) s.tropism = {p[0], p[1], p[2]};
        break;
    case TurtleAction::Sphere:
        out.addSphere(frameOf(s), 0.5f * (p.empty() ? s.width : p[0]), s.material, s.joint);
        break;
    case TurtleAction::Surface:
        out.addSurface(command.surface, frameOf(s), p.empty() ? 1.0f : p[0], s.material, s.joint);
        break;
    case TurtleAction::PolygonBegin: stack.polygons.push_back({frameOf(s), s.material, s.joint, {}}); break;
    case TurtleAction::PolygonVertex: addVertex(stack, s.position); break;
    case TurtleAction::PolygonEnd: closePolygon(stack, out); break;
    }
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

PlantAsset interpretPlant(const ModuleString& string, const SymbolTable& symbols, const TurtleSettings& settings,
                          const SurfaceLibrary& surfaces) {
    const std::vector<TurtleCommand> commands = turtleCommands(symbols);
    PlantAssetBuilder builder(surfaces);
    TurtleState state = initialTurtleState(settings);
    TurtleStack stack;
    interpretModules(string, commands, settings, state, stack, builder);
    return builder.finish();
}

PlantAsset plantFromGrammar(const Grammar& grammar, const ModuleString& derived, const SurfaceLibrary& surfaces) {
    const TurtleSettings settings = turtleSettings(grammar);
    if (grammar.interpretation.empty()) return interpretPlant(derived, grammar.symbols, settings, surfaces);
    return interpretPlant(applyInterpretation(grammar, derived), grammar.symbols, settings, surfaces);
}

} // namespace lsys
