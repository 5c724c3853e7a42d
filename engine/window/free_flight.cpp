#include "engine/window/free_flight.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace pf {
namespace {

float clampPitch(float pitch) {
    const float limit = glm::radians(kMaxPitchDegrees);
    return glm::clamp(pitch, -limit, limit);
}

} // namespace

glm::vec3 flightDirection(const FreeFlight& flight) {
    const float cosPitch = std::cos(flight.pitch);
    return {std::sin(flight.yaw) * cosPitch, std::sin(flight.pitch), -std::cos(flight.yaw) * cosPitch};
}

FreeFlight flightFromCamera(const Camera& camera) {
    FreeFlight flight;
    flight.position = camera.position;
    const glm::vec3 toTarget = camera.target - camera.position;
    const float length = glm::length(toTarget);
    if (length == 0.0f) return flight;
    const glm::vec3 direction = toTarget / length;
    flight.yaw = std::atan2(direction.x, -direction.z);
    flight.pitch = clampPitch(std::asin(glm::clamp(direction.y, -1.0f, 1.0f)));
    return flight;
}

void updateFlight(FreeFlight& flight, const FlightInput& input, float dt) {
    if (input.looking) {
        // Cursor right turns right (yaw grows); cursor down (+y) looks down.
        flight.yaw =
            std::remainder(flight.yaw + input.mouseDelta.x * flight.lookRadiansPerPixel, 2.0f * glm::pi<float>());
        flight.pitch = clampPitch(flight.pitch - input.mouseDelta.y * flight.lookRadiansPerPixel);
    }

    const glm::vec3 forward = flightDirection(flight);
    const glm::vec3 right{std::cos(flight.yaw), 0.0f, std::sin(flight.yaw)};
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 move{0.0f};
    if (input.forward) move += forward;
    if (input.back) move -= forward;
    if (input.right) move += right;
    if (input.left) move -= right;
    if (input.up) move += up;
    if (input.down) move -= up;
    const float length = glm::length(move);
    if (length == 0.0f) return;
    const float speed = flight.speed * (input.fast ? kFastFlightFactor : 1.0f);
    flight.position += move / length * speed * dt;
}

Camera cameraFromFlight(const FreeFlight& flight, const Camera& lensFrom) {
    Camera camera = lensFrom;
    camera.position = flight.position;
    camera.target = flight.position + flightDirection(flight);
    return camera;
}

} // namespace pf
