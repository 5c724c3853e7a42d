#include "lsystem/instancing/instance_key.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "lsystem/instancing/status_function.h"

namespace lsys {

namespace {

std::array<int32_t, 3> exactDirection(glm::vec3 v) {
    return {std::bit_cast<int32_t>(v.x), std::bit_cast<int32_t>(v.y), std::bit_cast<int32_t>(v.z)};
}

// A vector in local coordinates (heading +Y, left -X, up +Z) by its length and
// its cell in (polar angle from the heading, azimuth about it). Within a pole
// cap the tropism bend is at most e*sin(pi/G) whatever the azimuth, so caps
// may be one cell (mergePoles); `$` turns to the azimuth itself, so not for it.
std::array<int32_t, 3> quantisedDirection(glm::vec3 v, int granularity, bool mergePoles) {
    const float length = glm::length(v);
    // Zero, huge or not finite (a parameter can be anything): no cell, the bits.
    if (!(length > 0.0f && length < 1e6f)) return exactDirection(v);
    const int32_t lengthKey = static_cast<int32_t>(std::lround(static_cast<double>(length) * 65536.0));
    const double cell = M_PI / granularity;
    const double polar = std::acos(std::clamp(static_cast<double>(v.y / length), -1.0, 1.0));
    const int32_t polarCell = std::min(static_cast<int32_t>(polar / cell), granularity - 1);
    if (mergePoles && (polarCell == 0 || polarCell == granularity - 1)) return {lengthKey, polarCell, 0};
    const double azimuth = std::atan2(static_cast<double>(v.z), static_cast<double>(-v.x)) + M_PI;
    const int32_t azimuthCell = std::min(static_cast<int32_t>(azimuth / cell), 2 * granularity - 1);
    return {lengthKey, polarCell, azimuthCell};
}

std::array<int32_t, 3> directionKey(glm::vec3 v, int granularity, bool mergePoles) {
    return granularity > 0 ? quantisedDirection(v, granularity, mergePoles) : exactDirection(v);
}

// The world's +Y seen from a frame of that orientation.
glm::vec3 worldUpSeenFrom(const glm::quat& orientation) {
    return glm::conjugate(orientation) * glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

size_t StyleKeyHash::operator()(const StyleKey& key) const {
    static_assert(sizeof(StyleKey) == 18 * sizeof(uint32_t), "StyleKey must be 32-bit words only");
    std::array<uint32_t, 18> words;
    std::memcpy(words.data(), &key, sizeof(key));
    uint64_t hash = 0x9e3779b97f4a7c15ull;
    for (uint32_t word : words) hash = (hash ^ word) * 0x100000001b3ull + (hash >> 29);
    return static_cast<size_t>(hash);
}

StyleKey styleKey(const ObjectEntry& entry, uint16_t mask, int granularity) {
    StyleKey key;
    key.mask = mask;
    const TurtleState& s = entry.style;
    const uint32_t scalars[6] = {std::bit_cast<uint32_t>(s.width),     std::bit_cast<uint32_t>(s.length),
                                 std::bit_cast<uint32_t>(s.angle),     s.material,
                                 std::bit_cast<uint32_t>(s.stiffness), std::bit_cast<uint32_t>(s.elasticity)};
    for (size_t i = 0; i < 6; ++i)
        if (mask & (1u << i)) key.scalars[i] = scalars[i];
    if (mask & kSourceTropism) key.tropism = directionKey(s.tropism, granularity, true);
    if (mask & kSourceWorldUp) key.worldUp = directionKey(worldUpSeenFrom(entry.orientation), granularity, false);
    if (mask & kSourceOrientation) {
        const glm::quat q = entry.orientation.w < 0.0f ? -entry.orientation : entry.orientation;
        key.orientation = {std::bit_cast<uint32_t>(q.w), std::bit_cast<uint32_t>(q.x), std::bit_cast<uint32_t>(q.y),
                           std::bit_cast<uint32_t>(q.z)};
    }
    if (mask & kSourcePolygon) key.polygon = entry.polygonOpen ? 1 : 0;
    return key;
}

} // namespace lsys
