#include "sample_plants.h"

#include <stdexcept>

#include <glm/gtc/quaternion.hpp>

#include "lsystem/language/parser.h"

namespace plantfield::test {
namespace {

void addSegment(lsys::PlantAsset& asset, int32_t parent, lsys::Frame frame, float length, float startRadius,
                float endRadius) {
    const auto joint = int32_t(asset.joints.size());
    asset.joints.push_back({parent, frame, length, startRadius, endRadius, 0.0f});
    asset.primitives.push_back({frame, lsys::PrimitiveKind::Segment, 0, joint, 0, length, startRadius, endRadius});
}

lsys::Frame turned(const glm::vec3& position, float degreesAboutZ) {
    return {position, glm::angleAxis(glm::radians(degreesAboutZ), glm::vec3(0, 0, 1))};
}

} // namespace

glm::vec3 segmentTip(const lsys::PlantAsset& asset, size_t index) {
    const lsys::Primitive& p = asset.primitives.at(index);
    return p.frame.position + p.length * (p.frame.rotation * glm::vec3(0, 1, 0));
}

lsys::PlantAsset samplePlant() {
    lsys::PlantAsset asset;
    asset.materials = {{"bark", glm::vec3(0.4f, 0.3f, 0.2f), false}, {"leaf green", glm::vec3(0.2f, 0.6f, 0.1f), true}};

    addSegment(asset, -1, turned(glm::vec3(0.0f), 0.0f), 1.0f, 0.1f, 0.08f);
    addSegment(asset, 0, turned(segmentTip(asset, 0), 30.0f), 1.0f, 0.08f, 0.064f);
    addSegment(asset, 1, turned(segmentTip(asset, 1), 60.0f), 1.0f, 0.064f, 0.0512f);
    addSegment(asset, 0, turned(segmentTip(asset, 0), -45.0f), 0.5f, 0.03f, 0.03f);
    addSegment(asset, 3, turned(segmentTip(asset, 3), -45.0f), 0.2f, 0.0f, 0.0f);

    asset.primitives.push_back(
        {lsys::Frame{segmentTip(asset, 2)}, lsys::PrimitiveKind::Sphere, 0, 2, 0, 0.0f, 0.05f, 0.05f});

    asset.surfaces.push_back(
        {"leaf", {{0, 0, 0}, {0.1f, 0.5f, 0}, {0, 1, 0}, {-0.1f, 0.5f, 0}}, {}, {}, {0, 1, 2, 0, 2, 3}});
    asset.primitives.push_back({turned(segmentTip(asset, 3), -90.0f), lsys::PrimitiveKind::Surface, 1, 3, 0, 0.3f});
    asset.primitives.push_back({turned(segmentTip(asset, 1), 90.0f), lsys::PrimitiveKind::Surface, 1, 1, 0, 0.3f});

    const glm::vec3 corner = segmentTip(asset, 2);
    asset.polygons.push_back({{corner, corner + glm::vec3(2, 0, 0), corner + glm::vec3(2, 1, 0),
                               corner + glm::vec3(1, 1, 0), corner + glm::vec3(1, 2, 0), corner + glm::vec3(0, 2, 0)}});
    asset.primitives.push_back({lsys::Frame{corner}, lsys::PrimitiveKind::Polygon, 1, 2, 0});
    return asset;
}

lsys::PlantAsset helixPlant(int segments) {
    lsys::PlantAsset asset;
    asset.materials = {{"bark", glm::vec3(0.4f, 0.3f, 0.2f), false}};
    const glm::quat turn = glm::angleAxis(glm::radians(25.0f), glm::normalize(glm::vec3(1, 0.3f, 0.5f)));
    lsys::Frame frame;
    for (int i = 0; i < segments; ++i) {
        const float start = 0.1f * float(segments - i) / float(segments),
                    end = 0.1f * float(segments - i - 1) / float(segments);
        addSegment(asset, i - 1, frame, 0.2f, start, end);
        frame = {segmentTip(asset, size_t(i)), frame.rotation * turn};
    }
    return asset;
}

lsys::InstanceGraph sampleGraph() {
    const char* source =
        "angle: 30\n"
        "derivation length: 3\n"
        "Axiom: A(3)\n"
        "A(n) : n > 0 --> F(1,0.1)[+A(n-1)~leaf(0.5)][-;(2)@O(0.2)~petal(0.3)]F(1,0.08)[;(1){.f.+f.+f.}]/(90)A(n-1)\n";
    lsys::ParseResult parsed = lsys::parseLsystem(source);
    if (!parsed.ok()) throw std::runtime_error("sampleGraph: the grammar does not parse");
    lsys::BGrammarOptions options;
    options.interpreted = true;
    return lsys::buildInstanceGraph(lsys::buildBGrammar(parsed.grammar, options), parsed.grammar);
}

} // namespace plantfield::test
