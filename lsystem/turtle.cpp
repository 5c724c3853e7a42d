#include "lsystem/turtle.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "lsystem/rewriter.h"

namespace lsys {

namespace {

enum class Action : uint8_t {
    None, Draw, Move, Yaw, YawBack, Pitch, PitchBack, Roll, RollBack, TurnAround, RollHorizontal,
    Push, Pop, Width, Material, NextMaterial, Cut,
    ScaleLength, AddLength, SetLength, ScaleAngle, AddAngle, SetAngle, ScaleWidth, AddWidth, AddMaterial,
};

Action actionOf(const std::string& name) {
    if (name == "F") return Action::Draw;
    if (name == "f") return Action::Move;
    if (name == "+") return Action::Yaw;
    if (name == "-") return Action::YawBack;
    if (name == "&") return Action::Pitch;
    if (name == "^") return Action::PitchBack;
    if (name == "\\") return Action::Roll;
    if (name == "/") return Action::RollBack;
    if (name == "|") return Action::TurnAround;
    if (name == "$") return Action::RollHorizontal;
    if (name == "[") return Action::Push;
    if (name == "]") return Action::Pop;
    if (name == "!") return Action::Width;
    if (name == ";") return Action::Material;
    if (name == "'") return Action::NextMaterial;
    if (name == "%") return Action::Cut;
    if (name == "@Lm") return Action::ScaleLength;
    if (name == "@La") return Action::AddLength;
    if (name == "@Ls") return Action::SetLength;
    if (name == "@Am") return Action::ScaleAngle;
    if (name == "@Aa") return Action::AddAngle;
    if (name == "@As") return Action::SetAngle;
    if (name == "@Wm") return Action::ScaleWidth;
    if (name == "@Wa") return Action::AddWidth;
    if (name == "@Ca") return Action::AddMaterial;
    return Action::None;
}

struct State {
    glm::vec3 position{0.0f};
    glm::vec3 heading{0.0f, 1.0f, 0.0f};
    glm::vec3 left{-1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float width = 1.0f;
    float length = 1.0f;  // of a bare F or f
    float angle = 45.0f;  // of a bare turn, degrees
    uint32_t material = 0;
    int32_t lastSegment = -1;

    // Rotates the two frame vectors other than axis by degrees about axis,
    // then re-orthonormalises so rounding does not accumulate.
    void rotate(glm::vec3 axis, float degrees) {
        glm::quat rotation = glm::angleAxis(glm::radians(degrees), axis);
        heading = rotation * heading;
        left = rotation * left;
        up = rotation * up;
        orthonormalize();
    }

    void orthonormalize() {
        heading = glm::normalize(heading);
        left = glm::normalize(left - glm::dot(left, heading) * heading);
        up = glm::cross(heading, left);
    }

    // ABOP's $: L = V x H / |V x H| with V the world up (+Y).
    void rollHorizontal() {
        glm::vec3 horizontalLeft = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), heading);
        if (glm::length(horizontalLeft) < 1e-6f) return;  // heading vertical: any roll is horizontal
        left = glm::normalize(horizontalLeft);
        up = glm::cross(heading, left);
    }
};

// Parameters are arbitrary floats: negative, huge or NaN indices become 0.
uint32_t materialIndex(float value) {
    return value >= 0.0f && value < 65536.0f ? static_cast<uint32_t>(value) : 0;
}

// Index just past the ']' closing the branch that contains position i (or the end).
size_t endOfBranch(const ModuleString& string, size_t i) {
    int depth = 0;
    for (; i < string.size(); ++i) {
        if (string.symbols[i] == kPush) ++depth;
        if (string.symbols[i] == kPop && depth-- == 0) return i;
    }
    return i;
}

}  // namespace

TurtleSettings turtleSettings(const Grammar& grammar) {
    return {static_cast<float>(grammar.angle), static_cast<float>(grammar.step), static_cast<float>(grammar.width)};
}

std::vector<TurtleSegment> interpretTurtle(const ModuleString& string, const SymbolTable& symbols,
                                           const TurtleSettings& settings) {
    std::vector<Action> actions(symbols.size());
    for (size_t id = 0; id < symbols.size(); ++id) actions[id] = actionOf(symbols.name(static_cast<SymbolId>(id)));

    std::vector<TurtleSegment> segments;
    std::vector<State> stack;
    State state;
    state.width = settings.width;
    state.length = settings.step;
    state.angle = settings.angle;
    for (size_t i = 0; i < string.size(); ++i) {
        const std::span<const float> p = string.parameters(i);
        const float angle = p.empty() ? state.angle : p[0];
        // Of the length, angle, width and material modules: bare ones change nothing.
        const float factor = p.empty() ? 1.0f : p[0];
        const float amount = p.empty() ? 0.0f : p[0];
        switch (actions[string.symbols[i]]) {
            case Action::None: break;
            case Action::Draw: {
                const float length = p.empty() ? state.length : p[0];
                const float startWidth = state.width;
                if (p.size() > 1) state.width = p[1];
                glm::vec3 end = state.position + state.heading * length;
                segments.push_back({state.position, end, startWidth * 0.5f, state.width * 0.5f, state.material, state.lastSegment});
                state.lastSegment = static_cast<int32_t>(segments.size() - 1);
                state.position = end;
                break;
            }
            case Action::Move: state.position += state.heading * (p.empty() ? state.length : p[0]); break;
            case Action::Yaw: state.rotate(state.up, angle); break;
            case Action::YawBack: state.rotate(state.up, -angle); break;
            case Action::Pitch: state.rotate(state.left, angle); break;
            case Action::PitchBack: state.rotate(state.left, -angle); break;
            case Action::Roll: state.rotate(state.heading, angle); break;
            case Action::RollBack: state.rotate(state.heading, -angle); break;
            case Action::TurnAround: state.rotate(state.up, 180.0f); break;
            case Action::RollHorizontal: state.rollHorizontal(); break;
            case Action::Push: stack.push_back(state); break;
            case Action::Pop:
                if (!stack.empty()) {
                    state = stack.back();
                    stack.pop_back();
                }
                break;
            case Action::Width: state.width = p.empty() ? state.width * settings.widthFactor : p[0]; break;
            case Action::Material:
                state.material = p.empty() ? state.material + 1 : materialIndex(p[0]);
                break;
            case Action::NextMaterial: ++state.material; break;
            case Action::Cut: i = endOfBranch(string, i + 1) - 1; break;
            case Action::ScaleLength: state.length *= factor; break;
            case Action::AddLength: state.length += amount; break;
            case Action::SetLength: if (!p.empty()) state.length = p[0]; break;
            case Action::ScaleAngle: state.angle *= factor; break;
            case Action::AddAngle: state.angle += amount; break;
            case Action::SetAngle: if (!p.empty()) state.angle = p[0]; break;
            case Action::ScaleWidth: state.width *= factor; break;
            case Action::AddWidth: state.width += amount; break;
            case Action::AddMaterial: state.material = materialIndex(static_cast<float>(state.material) + amount); break;
        }
    }
    return segments;
}

std::vector<TurtleSegment> turtleSegments(const Grammar& grammar, const ModuleString& derived) {
    TurtleSettings settings = turtleSettings(grammar);
    if (grammar.interpretation.empty()) return interpretTurtle(derived, grammar.symbols, settings);
    return interpretTurtle(applyInterpretation(grammar, derived), grammar.symbols, settings);
}

}  // namespace lsys
