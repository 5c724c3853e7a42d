// cameraAt: Catmull-Rom through timed keyframes, held at the ends.
#include "engine/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf {
namespace {

constexpr float kTolerance = 1e-4f;

void expectNear(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(actual.x, expected.x, kTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTolerance);
}

CameraPath curvedPath() {
    CameraPath path;
    path.fovYDegrees = 50.0f;
    path.keyframes = {{0.0, {0, 5, 20}, {0, 0, 0}, 40.0f},
                      {2.0, {20, 8, 0}, {0, 1, 0}, std::nullopt},
                      {5.0, {0, 4, -20}, {5, 0, 0}, 70.0f},
                      {6.0, {-20, 6, 0}, {0, 0, 0}, std::nullopt}};
    return path;
}

TEST(CameraPath, PassesThroughEveryKeyframe) {
    const CameraPath path = curvedPath();
    for (const CameraKeyframe& key : path.keyframes) {
        const Camera camera = cameraAt(path, key.time);
        expectNear(camera.position, key.position);
        expectNear(camera.target, key.target);
        EXPECT_NEAR(camera.fovYDegrees, key.fovYDegrees.value_or(path.fovYDegrees), kTolerance);
    }
}

TEST(CameraPath, HoldsTheEndKeyframesOutsideThePath) {
    const CameraPath path = curvedPath();
    expectNear(cameraAt(path, -3.0).position, path.keyframes.front().position);
    expectNear(cameraAt(path, 100.0).position, path.keyframes.back().position);
    expectNear(cameraAt(path, 100.0).target, path.keyframes.back().target);
}

TEST(CameraPath, NotANumberIsTheStartOfThePath) {
    const CameraPath path = curvedPath();
    const Camera camera = cameraAt(path, std::nan(""));
    expectNear(camera.position, path.keyframes.front().position);
    expectNear(camera.target, path.keyframes.front().target);
    expectNear(cameraAt(CameraPath{}, std::nan("")).position, cameraAt(CameraPath{}, 0.0).position);
}

TEST(CameraPath, UnevenlyTimedKeysOnALineGiveConstantVelocity) {
    // x = 10 t sampled at uneven times: tangents from the keys' times keep
    // the motion linear, where a spline ignoring time would speed up and slow down.
    CameraPath path;
    for (double t : {0.0, 1.0, 3.0, 3.5, 6.0}) path.keyframes.push_back({t, {10 * float(t), 2, 0}, {0, 0, -10}});
    for (double t = 0.0; t <= 6.0; t += 0.25) expectNear(cameraAt(path, t).position, {10 * float(t), 2, 0});
}

TEST(CameraPath, CurvesSmoothlyBetweenKeys) {
    const CameraPath path = curvedPath();
    const glm::vec3 mid = cameraAt(path, 1.0).position;
    // Not the straight chord between the keys: the spline bends toward the next key.
    const glm::vec3 chord = 0.5f * (path.keyframes[0].position + path.keyframes[1].position);
    EXPECT_GT(glm::length(mid - chord), 1.0f);
    // The velocity is continuous across an interior key.
    const double h = 1e-3;
    const glm::vec3 before = (cameraAt(path, 2.0).position - cameraAt(path, 2.0 - h).position) / float(h);
    const glm::vec3 after = (cameraAt(path, 2.0 + h).position - cameraAt(path, 2.0).position) / float(h);
    EXPECT_LT(glm::length(before - after), 0.05f * glm::length(before));
}

TEST(CameraPath, SingleKeyframeHoldsStill) {
    CameraPath path;
    path.keyframes = {{3.0, {1, 2, 3}, {0, 0, 0}}};
    expectNear(cameraAt(path, 0.0).position, {1, 2, 3});
    expectNear(cameraAt(path, 9.0).position, {1, 2, 3});
}

TEST(CameraPath, EmptyPathOrbitsTheOrigin) {
    const CameraPath path;
    const Camera a = cameraAt(path, 0.0), b = cameraAt(path, 10.0);
    EXPECT_NEAR(glm::length(glm::vec2(a.position.x, a.position.z)), 60.0f, kTolerance);
    EXPECT_NEAR(a.position.y, 20.0f, kTolerance);
    expectNear(a.target, {0, 2, 0});
    EXPECT_GT(glm::length(a.position - b.position), 1.0f); // it moves
    EXPECT_EQ(a.fovYDegrees, path.fovYDegrees);
}

TEST(CameraPath, CarriesThePathsLens) {
    CameraPath path = curvedPath();
    path.nearPlane = 0.3f;
    path.farPlane = 500.0f;
    const Camera camera = cameraAt(path, 1.0);
    EXPECT_EQ(camera.nearPlane, 0.3f);
    EXPECT_EQ(camera.farPlane, 500.0f);
}

TEST(TimesAlongPath, SpreadsEvenlyFromTheFirstKeyframeToTheLast) {
    const CameraPath path = curvedPath(); // keys at 0, 2, 5, 6 s
    EXPECT_EQ(timesAlongPath(path, 4), (std::vector<double>{0.0, 2.0, 4.0, 6.0}));
    EXPECT_EQ(timesAlongPath(path, 1), std::vector<double>{0.0});
    const std::vector<double> many = timesAlongPath(path, 25);
    ASSERT_EQ(many.size(), 25u);
    EXPECT_EQ(many.front(), 0.0);
    EXPECT_EQ(many.back(), 6.0);
    for (size_t i = 1; i < many.size(); ++i) EXPECT_NEAR(many[i] - many[i - 1], 0.25, 1e-12);
}

TEST(TimesAlongPath, StepsThroughOneTurnOfTheDefaultOrbit) {
    const std::vector<double> times = timesAlongPath(CameraPath{}, 4);
    EXPECT_EQ(times, (std::vector<double>{0.0, 30.0, 60.0, 90.0}));
    // A full turn later the orbit is back where it began, so 120 s is not among them.
    expectNear(cameraAt(CameraPath{}, 120.0).position, cameraAt(CameraPath{}, 0.0).position);
}

} // namespace
} // namespace pf
