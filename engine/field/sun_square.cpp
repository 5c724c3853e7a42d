#include "engine/field/sun_square.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace pf {

SunSquare sunSquareAround(const glm::vec3& sunDirection, const glm::vec3& focus, float radius, uint32_t texels) {
    SunSquare square;
    const glm::vec3 up = std::abs(sunDirection.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    square.view = glm::lookAtRH(glm::vec3(0.0f), -sunDirection, up);
    square.texels = texels;
    square.texel = 2.0f * radius / float(texels);
    // The focus, seen from the sun, snapped to the texel grid.
    const glm::vec3 centre = glm::vec3(square.view * glm::vec4(focus, 1.0f));
    const glm::ivec2 half(int(texels / 2));
    square.origin =
        glm::ivec2(int(std::floor(centre.x / square.texel)), int(std::floor(centre.y / square.texel))) - half;
    // View space looks down -z: depths are distances along it.
    square.depth = -centre.z;
    return square;
}

SunSquare grownSquare(const SunSquare& square, uint32_t margin) {
    SunSquare grown = square;
    grown.origin -= glm::ivec2(int(margin));
    grown.texels += 2 * margin;
    return grown;
}

bool squareContains(const SunSquare& outer, const SunSquare& inner) {
    const glm::ivec2 start = inner.origin - outer.origin;
    const int room = int(outer.texels) - int(inner.texels);
    return start.x >= 0 && start.y >= 0 && start.x <= room && start.y <= room;
}

glm::mat4 sunViewProjection(const SunSquare& square, float depthRadius) {
    const glm::vec2 low = glm::vec2(square.origin) * square.texel;
    const glm::vec2 high = glm::vec2(square.origin + glm::ivec2(int(square.texels))) * square.texel;
    const glm::mat4 proj =
        glm::orthoRH_ZO(low.x, high.x, low.y, high.y, square.depth - depthRadius, square.depth + depthRadius);
    return proj * square.view;
}

} // namespace pf
