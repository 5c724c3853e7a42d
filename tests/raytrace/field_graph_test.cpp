// The field's graph (engine/raytrace/field_graph.h) traced by the GPU
// traversal against every triangle of every plant placed in world space and
// tested one by one on the CPU: the instances' yaw, scale and position and
// the models' BVHs must lose no hit and make none up. On lavapipe with the
// validation layer on.

#include "gpu_test.h"

#include "engine/raytrace/field_graph.h"
#include "engine/raytrace/raytrace_pass.h"
#include "engine/scene/field_content.h"
#include "lsystem/raytrace/intersect.h"
#include "seeded_rays.h"

#include <glm/gtc/quaternion.hpp>

#include <cstdio>
#include <optional>

namespace pf::test {
namespace {

struct WorldTriangle {
    glm::vec3 a, b, c;
};

struct PlacedField {
    std::vector<WorldTriangle> triangles;
    std::vector<lsys::Bounds> plantBounds;
};

// Every full-detail triangle of every plant, as plantToWorld (shaders/field_common.glsl) places it.
PlacedField placedField(const FieldContent& content) {
    PlacedField field;
    std::vector<WorldTriangle>& triangles = field.triangles;
    const PlantModelPool& pool = content.models;
    for (const gpu::FieldInstance& plant : fieldInstancesOf(content)) {
        const glm::quat yaw = glm::angleAxis(plant.orientation.x, glm::vec3(0.0f, 1.0f, 0.0f));
        auto place = [&](const gpu::FieldVertex& v) {
            return glm::vec3(plant.positionScale) + yaw * (glm::vec3(v.position) * plant.positionScale.w);
        };
        lsys::Bounds& bounds = field.plantBounds.emplace_back();
        for (const MeshRange& mesh : pool.models[plant.ids.x].meshes[LOD_FULL])
            for (uint32_t i = 0; i + 2 < mesh.indexCount; i += 3) {
                const uint32_t* corner = &pool.indices[mesh.firstIndex + i];
                triangles.push_back({place(pool.vertices[mesh.vertexOffset + corner[0]]),
                                     place(pool.vertices[mesh.vertexOffset + corner[1]]),
                                     place(pool.vertices[mesh.vertexOffset + corner[2]])});
                for (const glm::vec3& p : {triangles.back().a, triangles.back().b, triangles.back().c})
                    bounds.extend(p);
            }
    }
    return field;
}

std::optional<float> nearestOf(const std::vector<WorldTriangle>& triangles, const lsys::Ray& ray) {
    std::optional<float> nearest;
    for (const WorldTriangle& t : triangles)
        if (const std::optional<lsys::ShapeHit> hit = lsys::intersectTriangle(ray, t.a, t.b, t.c))
            if (!nearest || hit->t < *nearest) nearest = hit->t;
    return nearest;
}

class FieldGraphTest : public GpuTest {};

// test_culling.json's fourteen bushes, each scaled and yawed its own way.
TEST_F(FieldGraphTest, HitsAreThoseOfEveryPlacedTriangle) {
    FieldContent content = buildFieldContent(loadScene(PLANTFIELD_DATA_DIR "/scenes/test_culling.json"));
    for (size_t p = 0; p < content.plants.size(); ++p) {
        content.plants[p].scale = 0.6f + 0.1f * float(p);
        content.plants[p].rotation = 0.45f * float(p);
    }
    const std::vector<gpu::FieldInstance> plants = fieldInstancesOf(content);
    const GpuGraph packed = packFieldGraph(content.models, plants);
    EXPECT_EQ(packed.instances.size(), plants.size());
    EXPECT_EQ(packed.levels, 2u);
    const PlacedField field = placedField(content);
    const std::vector<WorldTriangle>& triangles = field.triangles;

    // Rays at each plant in turn, from around it: some pass by it into its neighbours.
    constexpr size_t kRaysPerPlant = 100;
    std::vector<lsys::Ray> rays;
    for (size_t p = 0; p < plants.size(); ++p)
        for (const lsys::Ray& ray : lsys::test::raysAt(field.plantBounds[p], kRaysPerPlant, uint32_t(11 + p)))
            rays.push_back(ray);
    const size_t kRays = rays.size();
    std::vector<gpu::RtRay> gpuRays;
    for (const lsys::Ray& ray : rays) gpuRays.push_back({ray.origin, ray.tMin, ray.direction, ray.tMax});
    const RaytracePass pass = createRaytracePass(resources, uploadGraph(resources, packed), kRays);
    const std::vector<gpu::RtHit> closest = traceRays(ctx, pass, gpuRays, lsys::HitQuery::Closest);
    const std::vector<gpu::RtHit> any = traceRays(ctx, pass, gpuRays, lsys::HitQuery::Any);

    size_t hits = 0, differing = 0;
    float largest = 0.0f;
    for (size_t i = 0; i < rays.size(); ++i) {
        const std::optional<float> expected = nearestOf(triangles, rays[i]);
        const bool gpuHit = closest[i].primitive != RAYTRACE_NO_HIT;
        hits += expected.has_value();
        EXPECT_EQ(any[i].primitive != RAYTRACE_NO_HIT, gpuHit) << "ray " << i;
        // A ray through a shared edge may hit on one side and miss on the
        // other in single precision: a few in a thousand at most.
        if (expected.has_value() != gpuHit) {
            ++differing;
            continue;
        }
        if (!expected) continue;
        EXPECT_EQ(closest[i].kind, RAYTRACE_KIND_POLYGON);
        const float relative = std::abs(closest[i].t - *expected) / *expected;
        largest = std::max(largest, relative);
        EXPECT_LT(relative, 1e-4f) << "ray " << i << ": CPU t " << *expected << ", GPU t " << closest[i].t;
    }
    std::printf("%zu rays over %zu triangles of %zu plants: %zu hit, %zu differ, t within %.2g\n", kRays,
                triangles.size(), plants.size(), hits, differing, largest);
    EXPECT_GT(hits, kRays / 5) << "the rays are aimed into the plants' boxes";
    EXPECT_LE(differing, kRays / 500);
}

// The models are packed, but with no plant there is no root for a ray to enter.
TEST_F(FieldGraphTest, AFieldOfNoPlantsHasNoRoot) {
    const FieldContent content = buildFieldContent(loadScene(PLANTFIELD_DATA_DIR "/scenes/test_culling.json"));
    const GpuGraph packed = packFieldGraph(content.models, {});
    EXPECT_EQ(packed.rootNode, RAYTRACE_NO_NODE);
    EXPECT_TRUE(packed.instances.empty());
}

} // namespace
} // namespace pf::test
