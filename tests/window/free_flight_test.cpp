// The free-flight camera controller: movement, mouse look, pitch limit and
// the round trip through Camera.
#include "engine/window/free_flight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pf::test {
namespace {

constexpr float kEpsilon = 1e-4f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kEpsilon) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(FreeFlightTest, ForwardMovesAlongTheViewBySpeedTimesDt) {
    FreeFlight flight;
    flight.position = {1.0f, 2.0f, 3.0f};
    flight.yaw = glm::radians(30.0f);
    flight.pitch = glm::radians(-20.0f);
    const glm::vec3 start = flight.position;
    const glm::vec3 view = flightDirection(flight);

    FlightInput input;
    input.forward = true;
    updateFlight(flight, input, 0.5f);
    expectNear(flight.position, start + view * (10.0f * 0.5f));
}

TEST(FreeFlightTest, FastIsFourTimesAndDiagonalsAreNotFaster) {
    FreeFlight flight;
    FlightInput input;
    input.forward = input.right = input.up = true;
    input.fast = true;
    updateFlight(flight, input, 0.1f);
    EXPECT_NEAR(glm::length(flight.position), 10.0f * kFastFlightFactor * 0.1f, kEpsilon);
}

TEST(FreeFlightTest, StrafeAndClimbFollowRightAndWorldUp) {
    FreeFlight flight; // yaw 0: looking toward -z, so right is +x
    flight.pitch = glm::radians(45.0f);
    FlightInput input;
    input.right = true;
    updateFlight(flight, input, 1.0f);
    expectNear(flight.position, {10.0f, 0.0f, 0.0f});

    flight.position = glm::vec3(0.0f);
    input = {};
    input.down = true;
    updateFlight(flight, input, 1.0f);
    expectNear(flight.position, {0.0f, -10.0f, 0.0f});
}

TEST(FreeFlightTest, MouseTurnsOnlyWhileLooking) {
    FreeFlight flight;
    FlightInput input;
    input.mouseDelta = {100.0f, 0.0f};
    updateFlight(flight, input, 0.016f);
    EXPECT_EQ(flight.yaw, 0.0f);

    input.looking = true;
    updateFlight(flight, input, 0.016f);
    EXPECT_NEAR(flight.yaw, 100.0f * flight.lookRadiansPerPixel, kEpsilon);
    // Turning right from north faces toward +x.
    EXPECT_GT(flightDirection(flight).x, 0.0f);
    EXPECT_EQ(flight.position, glm::vec3(0.0f));
}

TEST(FreeFlightTest, PitchClampsAtEightyNineDegrees) {
    FreeFlight flight;
    FlightInput input;
    input.looking = true;
    input.mouseDelta = {0.0f, -100000.0f}; // cursor far up: look up
    updateFlight(flight, input, 0.016f);
    EXPECT_NEAR(flight.pitch, glm::radians(kMaxPitchDegrees), kEpsilon);

    input.mouseDelta = {0.0f, 100000.0f};
    updateFlight(flight, input, 0.016f);
    EXPECT_NEAR(flight.pitch, -glm::radians(kMaxPitchDegrees), kEpsilon);
}

TEST(FreeFlightTest, CameraRoundTripKeepsPositionDirectionAndLens) {
    Camera camera;
    camera.position = {4.0f, 2.0f, 6.0f};
    camera.target = {-3.0f, 0.5f, 1.0f};
    camera.fovYDegrees = 60.0f;
    camera.farPlane = 500.0f;

    const Camera back = cameraFromFlight(flightFromCamera(camera), camera);
    expectNear(back.position, camera.position);
    expectNear(glm::normalize(back.target - back.position), glm::normalize(camera.target - camera.position));
    EXPECT_EQ(back.fovYDegrees, 60.0f);
    EXPECT_EQ(back.farPlane, 500.0f);
}

TEST(FreeFlightTest, CameraStraightDownIsClampedAndDegenerateLooksNorth) {
    Camera down;
    down.position = {0.0f, 10.0f, 0.0f};
    down.target = {0.0f, 0.0f, 0.0f};
    EXPECT_NEAR(flightFromCamera(down).pitch, -glm::radians(kMaxPitchDegrees), kEpsilon);

    Camera degenerate;
    degenerate.target = degenerate.position;
    const FreeFlight flight = flightFromCamera(degenerate);
    expectNear(flightDirection(flight), {0.0f, 0.0f, -1.0f});
}

} // namespace
} // namespace pf::test
