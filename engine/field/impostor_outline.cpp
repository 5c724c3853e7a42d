#include "engine/field/impostor_outline.h"

#include <limits>
#include <stdexcept>

namespace pf {

ImpostorOutline impostorOutline(std::span<const uint8_t> alpha, uint32_t size, float marginTexels) {
    if (size == 0 || alpha.size() != size_t(size) * size)
        throw std::runtime_error("impostor outline: alpha must hold size × size values");
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            if (alpha[size_t(y) * size + x] == 0) continue;
            lo = glm::min(lo, glm::vec2(x, y));
            hi = glm::max(hi, glm::vec2(x + 1, y + 1));
        }
    }
    if (lo.x > hi.x) return {glm::vec2(0.5f), glm::vec2(0.5f), glm::vec2(0.5f), glm::vec2(0.5f)};
    lo = glm::max(lo - marginTexels, glm::vec2(0.0f)) / float(size);
    hi = glm::min(hi + marginTexels, glm::vec2(float(size))) / float(size);
    return {lo, glm::vec2(hi.x, lo.y), hi, glm::vec2(lo.x, hi.y)};
}

float outlineArea(const ImpostorOutline& outline) {
    const glm::vec2 extent = outline[2] - outline[0];
    return extent.x * extent.y;
}

} // namespace pf
