#pragma once
// What an object of the InstanceGraph is keyed by: its node and the entry
// values its interpretation read (status_function.h's sources), with the
// orientation-dependent ones quantised by the granularity of the Calgary
// b-grammar thesis, §5.3.
// Internal to the builder (lsystem/instancing/instance_graph_build.cpp).

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>

#include "lsystem/turtle/turtle.h"

namespace lsys {

// The state an object is entered with, its frame factored out.
struct ObjectEntry {
    TurtleState style;     // frame unused; tropism in the entry frame's coordinates
    glm::quat orientation; // of the entry frame in plant space (for `$` and `@Tv`)
    bool polygonOpen = false;
};

// The entry values under a mask of sources, nothing else: all 32-bit words, so
// equality and hashing see no padding.
struct StyleKey {
    uint32_t mask = 0;
    std::array<uint32_t, 6> scalars{}; // width, length, angle, material, stiffness, elasticity (bits)
    std::array<int32_t, 3> tropism{};
    std::array<int32_t, 3> worldUp{};
    std::array<uint32_t, 4> orientation{};
    uint32_t polygon = 0;

    friend bool operator==(const StyleKey&, const StyleKey&) = default;
};

struct StyleKeyHash {
    size_t operator()(const StyleKey& key) const;
};

// granularity G = 0 keys directions exactly (their bits); G > 0 keys them by
// the cell of pi/G they fall in, in the polar angle from the entry heading and
// the azimuth about it (the tropism's pole caps one cell each), their length
// to 2^-16.
StyleKey styleKey(const ObjectEntry& entry, uint16_t mask, int granularity);

} // namespace lsys
