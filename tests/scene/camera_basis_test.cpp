// The camera's basis and depth range (engine/scene/camera.h,
// lsystem/common/view_up.h): defined looking straight down or up, the same
// as glm's look-at for every other camera, and a depth range that resolves a
// field seen from millions of metres.
#include "engine/scene/camera.h"
#include "engine/scene/field_content.h"
#include "lsystem/common/view_up.h"

#include <gtest/gtest.h>

#include <glm/ext/matrix_transform.hpp>

#include <cmath>

namespace pf {
namespace {

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Where a world point lands in normalised device coordinates.
glm::vec3 ndcOf(const Camera& camera, glm::vec3 point) {
    const glm::vec4 clip = projectionMatrix(camera, {640, 360}) * viewMatrix(camera) * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(CameraBasis, LookingStraightDownPutsEastRightAndNorthUp) {
    Camera camera;
    camera.position = {3.0f, 100.0f, -2.0f};
    camera.target = {3.0f, 0.0f, -2.0f};
    ASSERT_TRUE(finite(viewMatrix(camera)));
    const glm::vec3 east = ndcOf(camera, {13.0f, 0.0f, -2.0f});
    const glm::vec3 north = ndcOf(camera, {3.0f, 0.0f, -12.0f});
    EXPECT_GT(east.x, 0.05f);
    EXPECT_NEAR(east.y, 0.0f, 1e-5f);
    EXPECT_GT(north.y, 0.05f);
    EXPECT_NEAR(north.x, 0.0f, 1e-5f);
}

TEST(CameraBasis, LookingStraightUpIsDefined) {
    Camera camera;
    camera.position = {0.0f, 1.0f, 0.0f};
    camera.target = {0.0f, 50.0f, 0.0f};
    ASSERT_TRUE(finite(viewMatrix(camera)));
    EXPECT_GT(ndcOf(camera, {10.0f, 40.0f, 0.0f}).x, 0.05f);
}

// Every camera that does not look along the vertical keeps glm's look-at
// bit for bit, so ordinary frames do not change.
TEST(CameraBasis, AnObliqueCameraKeepsGlmsLookAt) {
    const glm::vec3 positions[] = {{60.0f, 20.0f, 35.0f}, {-20.0f, 5.0f, 35.0f}, {0.001f, 100.0f, 0.0f}};
    for (const glm::vec3& position : positions) {
        Camera camera;
        camera.position = position;
        camera.target = {0.0f, 2.0f, 0.0f};
        EXPECT_EQ(viewMatrix(camera), glm::lookAtRH(camera.position, camera.target, glm::vec3(0, 1, 0)));
    }
}

TEST(ViewUp, AnyFiniteLengthGivesAUnitPerpendicularRightVector) {
    for (const float length : {1e-30f, 1.0f, 1e30f})
        for (const float sign : {-1.0f, 1.0f}) {
            const glm::vec3 forward(0.0f, sign * length, 0.0f);
            const glm::vec3 up = lsys::viewUp(forward, {0.0f, 1.0f, 0.0f});
            const glm::vec3 right = glm::cross(glm::normalize(glm::vec3(0.0f, sign, 0.0f)), up);
            EXPECT_NEAR(right.x, 1.0f, 1e-6f) << length << " " << sign;
            EXPECT_NEAR(glm::length(up), 1.0f, 1e-6f);
        }
    // Leaning away from up: up itself.
    EXPECT_EQ(lsys::viewUp({1.0f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}), glm::vec3(0.0f, 1.0f, 0.0f));
}

constexpr SceneBox kField{{-150.0f, -5.0f, -150.0f}, {150.0f, 25.0f, 150.0f}};

// From 3·10⁶ m with the scene's 0.1 m near plane every depth rounds to 1:
// the field's near edge and its centre must land at distinct depths inside (0, 1).
TEST(DepthRange, AFieldMillionsOfMetresAwayGetsDistinctDepths) {
    for (const float distance : {1e5f, 3e6f, 1e7f}) {
        Camera camera;
        camera.position = {0.0f, 0.3f * distance, distance};
        camera.target = {0.0f, 0.0f, 0.0f};
        camera.nearPlane = 0.1f;
        camera.farPlane = 2000.0f;
        const Camera fitted = withDepthRangeFor(camera, kField);
        const float nearEdge = ndcOf(fitted, {0.0f, 25.0f, 150.0f}).z, centre = ndcOf(fitted, {0.0f, 10.0f, 0.0f}).z;
        EXPECT_GT(nearEdge, 0.0f) << distance;
        EXPECT_LT(nearEdge, centre) << distance;
        EXPECT_LT(centre, 1.0f) << distance;
    }
}

TEST(DepthRange, CamerasInsideOrNearTheFieldKeepTheirPlanes) {
    Camera inside;
    inside.position = {-20.0f, 5.0f, 35.0f};
    inside.target = {5.0f, 4.0f, 10.0f};
    Camera above;
    above.position = {60.0f, 80.0f, 0.0f};
    Camera outside; // 900 m from the field: within 10^4 of its 0.1 m near planes
    outside.position = {0.0f, 25.0f, 1050.0f};
    outside.nearPlane = 0.1f;
    for (const Camera& camera : {inside, above, outside}) {
        const Camera fitted = withDepthRangeFor(camera, kField);
        EXPECT_EQ(fitted.nearPlane, camera.nearPlane);
        EXPECT_EQ(fitted.farPlane, camera.farPlane);
    }
}

TEST(FieldBox, HoldsTheTerrainAndEveryPlant) {
    const FieldContent content = buildFieldContent(loadScene(PLANTFIELD_DATA_DIR "/scenes/test_small.json"));
    ASSERT_FALSE(content.plants.empty());
    const SceneBox box = fieldBox(content);
    for (const float height : content.terrain.heights) {
        EXPECT_GE(height, box.min.y);
        EXPECT_LE(height, box.max.y);
    }
    EXPECT_LE(box.min.x, -0.5f * content.terrain.size);
    EXPECT_GE(box.max.z, 0.5f * content.terrain.size);
    for (const PlantInstance& plant : content.plants) {
        const gpu::PlantModel& model = content.models.models[content.models.modelOf(plant.species, plant.variant)].gpu;
        EXPECT_LE(plant.position.y + model.boxMax.y * plant.scale, box.max.y);
        EXPECT_GE(plant.position.x - model.sphere.w * plant.scale, box.min.x);
    }
}

} // namespace
} // namespace pf
