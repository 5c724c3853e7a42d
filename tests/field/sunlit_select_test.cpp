// Which impostors the frame's shadow map cannot reach (shaders/shared/sunlit_select.h):
// CPU only, against the map's own view-projection (engine/field/shadow_map.h).
#include "engine/field/sun_square.h"
#include "shaders/shared/sunlit_select.h"

#include <gtest/gtest.h>

#include <random>

#include "sun_fixture.h"

namespace pf {
namespace {

using test::kRadius;
using test::kSun;
using test::kTexels;
constexpr float kDepthRadius = 250.0f;

// Where the map sees a world point: inside its square and before its far
// plane is where sunVisibility (field_common.glsl) looks it up.
bool mapReaches(const glm::mat4& sunViewProj, const glm::vec3& p) {
    const glm::vec4 clip = sunViewProj * glm::vec4(p, 1.0f);
    return std::abs(clip.x) <= 1.0f && std::abs(clip.y) <= 1.0f && clip.z <= 1.0f;
}

// A point uniformly inside the ball of `radius` around `centre`.
glm::vec3 pointInBall(std::mt19937& rng, const glm::vec3& centre, float radius) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (;;) {
        const glm::vec3 p(unit(rng), unit(rng), unit(rng));
        if (glm::dot(p, p) <= 1.0f) return centre + p * radius;
    }
}

TEST(SunlitImpostors, NoPointOfASunlitSphereIsInTheMap) {
    const SunSquare square = sunSquareAround(kSun, glm::vec3(5.0f, 0.0f, -3.0f), kRadius, kTexels);
    const glm::mat4 sunViewProj = sunViewProjection(square, kDepthRadius);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> ground(-200.0f, 200.0f), height(0.0f, 20.0f), size(0.5f, 15.0f);
    uint32_t sunlit = 0, shadowed = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec4 sphere(ground(rng), height(rng), ground(rng), size(rng));
        const uint32_t part = gpu::impostorPartOf(sphere, sunViewProj, square.texel, true);
        if (part == IMPOSTOR_PART_SHADOWED) {
            ++shadowed;
            continue;
        }
        ASSERT_EQ(part, IMPOSTOR_PART_SUNLIT);
        ++sunlit;
        // The quad may lean out of the sphere by the sway margin.
        const float reach = sphere.w * (1.0f + SUNLIT_SWAY_MARGIN);
        for (int k = 0; k < 64; ++k)
            ASSERT_FALSE(mapReaches(sunViewProj, pointInBall(rng, glm::vec3(sphere), reach)))
                << "sphere " << i << " at (" << sphere.x << ", " << sphere.y << ", " << sphere.z << ") r " << sphere.w;
    }
    // Both parts are populated: a 120 m map over a 400 m square of plants.
    EXPECT_GT(sunlit, 1000u);
    EXPECT_GT(shadowed, 200u);
}

TEST(SunlitImpostors, SpheresInsideOrAcrossTheMapAreShadowed) {
    const SunSquare square = sunSquareAround(kSun, glm::vec3(0.0f), kRadius, kTexels);
    const glm::mat4 sunViewProj = sunViewProjection(square, kDepthRadius);
    // The map's centre, and a sphere whose centre lies just outside the
    // square but whose edge reaches into it.
    EXPECT_EQ(gpu::impostorPartOf(glm::vec4(0.0f, 0.0f, 0.0f, 5.0f), sunViewProj, square.texel, true),
              IMPOSTOR_PART_SHADOWED);
    const glm::vec3 right(square.view[0][0], square.view[1][0], square.view[2][0]);
    const glm::vec3 justOutside = right * (kRadius + 3.0f);
    ASSERT_FALSE(mapReaches(sunViewProj, justOutside));
    EXPECT_EQ(gpu::impostorPartOf(glm::vec4(justOutside, 5.0f), sunViewProj, square.texel, true),
              IMPOSTOR_PART_SHADOWED);
    EXPECT_EQ(gpu::impostorPartOf(glm::vec4(right * (kRadius + 30.0f), 5.0f), sunViewProj, square.texel, true),
              IMPOSTOR_PART_SUNLIT);
}

TEST(SunlitImpostors, EveryImpostorIsSunlitWithoutShadows) {
    const SunSquare square = sunSquareAround(kSun, glm::vec3(0.0f), kRadius, kTexels);
    EXPECT_EQ(
        gpu::impostorPartOf(glm::vec4(0.0f, 0.0f, 0.0f, 5.0f), sunViewProjection(square, kDepthRadius), 0.0f, false),
        IMPOSTOR_PART_SUNLIT);
}

} // namespace
} // namespace pf
