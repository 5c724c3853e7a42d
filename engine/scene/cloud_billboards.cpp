#include "engine/scene/cloud_billboards.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pf {

std::vector<gpu::CloudBillboard> cloudBillboards(const std::vector<Cloud>& clouds, const Wind& wind, float time,
                                                 const glm::vec3& camera, const glm::vec3& forward) {
    const glm::vec3 drift = meanWindVelocity(wind) * time;
    std::vector<gpu::CloudBillboard> billboards;
    std::vector<float> depths;
    for (const Cloud& cloud : clouds)
        for (const CloudSphere& sphere : cloud.spheres) {
            const glm::vec3 centre = sphere.centre + drift;
            billboards.push_back({glm::vec4(centre, sphere.radius), glm::vec4(sphere.height, sphere.outward)});
            depths.push_back(glm::dot(centre - camera, forward));
        }
    std::vector<uint32_t> order(billboards.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return depths[a] > depths[b]; });
    std::vector<gpu::CloudBillboard> sorted;
    sorted.reserve(order.size());
    for (uint32_t i : order) sorted.push_back(billboards[i]);
    return sorted;
}

} // namespace pf
