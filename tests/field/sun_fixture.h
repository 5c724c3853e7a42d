#pragma once
// The sun and the shadow map's square shared by the field tests that check
// the shadow map (shadow_cache_test.cpp, sunlit_select_test.cpp).

#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pf::test {

inline const glm::vec3 kSun = glm::normalize(glm::vec3(0.4f, 0.62f, -0.5f));
inline constexpr float kRadius = 60.0f;   // half the side of the map's square, metres
inline constexpr uint32_t kTexels = 1024; // across the map

} // namespace pf::test
