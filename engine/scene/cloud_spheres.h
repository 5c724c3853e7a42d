// A cloud as the spheres its L-system draws (the clouds-and-mountains chapter, §23–24: "the shape of
// the cloud ... is built up by a large number of semi-transparent spheres",
// each made by the sphere symbol, here `@O(d)`). Everything else the turtle
// draws (segments, surfaces, polygons) is not part of the cloud.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

namespace pf {

struct CloudSphere {
    glm::vec3 centre{0.0f}; // metres
    float radius = 0.0f;    // metres
    float height = 0.0f;    // the centre's height within its cloud: 0 at the lowest centre, 1 at the highest
    // Unit normal of the ellipsoid fitted to the cloud's box at the centre
    // (zero at the box's middle): which side of the cloud the sphere is on.
    glm::vec3 outward{0.0f};
    bool operator==(const CloudSphere&) const = default;
};

// The most spheres one cloud may have: each is a blended billboard sorted
// every frame, and a few thousand already make a dense cumulus.
constexpr size_t kMaxCloudSpheres = 8192;
// The most spheres all the clouds of a scene may have together: the
// renderer sorts them all every frame and holds them in one buffer.
constexpr size_t kMaxSceneCloudSpheres = 65536;

// A cloud file that cannot be read, derived or drawn: the message says why
// (with the L-system's file:line:column where there is one).
struct CloudError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses, derives (with `seed` in place of the file's own when given) and
// interprets the L-system file `file`, keeping its spheres, then scales them
// uniformly so the cloud's bounding box is `size` metres at its widest and
// moves them so the middle of the box's bottom face lies at `base`. Same
// inputs ⇒ same spheres in the same (turtle) order. Throws CloudError for a
// malformed file, a derivation past its module budget, no sphere at all or
// more than kMaxCloudSpheres.
std::vector<CloudSphere> cloudSpheres(const std::filesystem::path& file, std::optional<uint32_t> seed, float size,
                                      const glm::vec3& base);

} // namespace pf
