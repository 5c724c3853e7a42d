#include "engine/default_scene.h"

#include "lsystem/parser.h"
#include "lsystem/rewriter.h"
#include "lsystem/turtle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pf {
namespace {

// ABOP Fig. 2.8 (Prusinkiewicz & Lindenmayer 1990): a ternary branching tree
// whose internodes lengthen and thicken with age. Built in so the default
// scene needs no data files.
constexpr const char* kDefaultTree = R"(
#define d1 94.74
#define d2 132.63
#define a 18.95
#define lr 1.109
#define vr 1.732
derivation length: 6
Axiom: !(1)F(200)/(45)A
p1: A --> !(vr)F(50)[&(a)F(50)A]/(d1)[&(a)F(50)A]/(d2)[&(a)F(50)A]
p2: F(l) --> F(l*lr)
p3: !(w) --> !(w*vr)
endlsystem
)";

constexpr float kTreeHeightMetres = 7.5f;
const glm::vec3 kBarkAlbedo{0.17f, 0.11f, 0.065f};

} // namespace

DefaultScene buildDefaultScene() {
    const lsys::ParseResult parsed = lsys::parseLsystem(kDefaultTree, {.file = "<default tree>"});
    if (!parsed.ok()) throw std::runtime_error("the built-in default tree does not parse");
    const lsys::ModuleString derived = lsys::derive(parsed.grammar);
    const lsys::PlantAsset plant = lsys::plantFromGrammar(parsed.grammar, derived);

    // The tree is all segments: each runs from its frame along its heading H.
    struct Span {
        glm::vec3 start, end;
        float startRadius, endRadius;
    };
    std::vector<Span> spans;
    for (const lsys::Primitive& p : plant.primitives)
        if (p.kind == lsys::PrimitiveKind::Segment)
            spans.push_back({p.frame.position, p.frame.position + p.frame.rotation * glm::vec3(0.0f, p.length, 0.0f),
                             p.startRadius, p.endRadius});

    // The grammar's units are arbitrary: scale the plant to a tree's height.
    float top = 0.0f;
    for (const Span& s : spans) top = std::max({top, s.start.y, s.end.y});
    const float scale = top > 0.0f ? kTreeHeightMetres / top : 1.0f;

    DefaultScene scene;
    scene.boundsMin = glm::vec3(std::numeric_limits<float>::max());
    scene.boundsMax = glm::vec3(std::numeric_limits<float>::lowest());
    for (const Span& s : spans) {
        const glm::vec3 start = s.start * scale, end = s.end * scale;
        scene.geometry.segments.push_back({glm::vec4(start, s.startRadius * scale),
                                           glm::vec4(end, s.endRadius * scale), glm::vec4(kBarkAlbedo, 0.0f)});
        scene.boundsMin = glm::min(scene.boundsMin, glm::min(start, end));
        scene.boundsMax = glm::max(scene.boundsMax, glm::max(start, end));
    }
    return scene;
}

Camera defaultCameraAt(const DefaultScene& scene, double t) {
    const glm::vec3 center = 0.5f * (scene.boundsMin + scene.boundsMax);
    const float radius = glm::length(scene.boundsMax - scene.boundsMin);
    const float angle = glm::radians(30.0f) + float(t) * 0.2f; // radians per second of scene time
    Camera camera;
    camera.target = center;
    camera.position = center + glm::vec3(std::sin(angle) * radius, 0.1f * radius, std::cos(angle) * radius);
    return camera;
}

} // namespace pf
