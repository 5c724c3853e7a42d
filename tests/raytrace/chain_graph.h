#pragma once
// A hand-made InstanceGraph as deep as asked: the GPU traversal's level and
// stack limits are tested on it.

#include <cstdint>

#include <glm/gtc/quaternion.hpp>

#include "lsystem/instancing/instance_graph.h"

namespace pf::test {

// A chain of `depth` objects, each drawing `segments` segments side by side
// and placing the one before it one unit up, turned a little about +Y.
inline lsys::InstanceGraph chainGraph(uint32_t depth, uint32_t segments) {
    lsys::InstanceGraph graph;
    for (uint32_t object = 0; object < depth; ++object) {
        lsys::GraphObject o;
        o.itemStart = uint32_t(graph.items.size());
        for (uint32_t s = 0; s < segments; ++s) {
            lsys::GraphPrimitive segment;
            segment.frame.position = glm::vec3(float(s), 0.0f, 0.0f);
            segment.length = 1.0f;
            segment.startRadius = segment.endRadius = 0.1f;
            graph.items.push_back({lsys::GraphItem::Kind::Primitive, uint32_t(graph.primitives.size())});
            graph.primitives.push_back(segment);
        }
        if (object > 0) {
            graph.items.push_back({lsys::GraphItem::Kind::Instance, uint32_t(graph.instances.size())});
            graph.instances.push_back(
                {object - 1, lsys::Frame{glm::vec3(0.0f, 1.0f, 0.0f), glm::angleAxis(0.2f, glm::vec3(0, 1, 0))}});
        }
        o.itemCount = uint32_t(graph.items.size()) - o.itemStart;
        graph.objects.push_back(o);
    }
    graph.root = depth - 1;
    return graph;
}

} // namespace pf::test
