// The window's free-flight camera controller: pure state and maths, fed by
// whatever reads the keyboard and mouse (engine/window/window_input.h).
//
// Conventions follow engine/scene/camera.h: y is up; yaw 0 looks toward -z (north)
// and grows clockwise seen from above, toward +x; pitch is positive upward.
#pragma once

#include "engine/scene/camera.h"

#include <glm/glm.hpp>

namespace pf {

struct FlightInput {
    bool forward = false, back = false;
    bool left = false, right = false;
    bool up = false, down = false;
    bool fast = false;          // speed times kFastFlightFactor
    glm::vec2 mouseDelta{0.0f}; // pixels since the last update, y down
    bool looking = false;       // mouseDelta turns the view only while true
};

constexpr float kFastFlightFactor = 4.0f;
constexpr float kMaxPitchDegrees = 89.0f; // short of straight up/down, where yaw is undefined

struct FreeFlight {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;                   // radians
    float pitch = 0.0f;                 // radians, within +-kMaxPitchDegrees
    float speed = 10.0f;                // metres per second
    float lookRadiansPerPixel = 0.003f; // mouse sensitivity
};

// Unit view direction for a yaw and pitch.
glm::vec3 flightDirection(const FreeFlight& flight);

// Position and view direction of the camera; the pitch is clamped to
// +-kMaxPitchDegrees. A camera whose target equals its position looks north.
FreeFlight flightFromCamera(const Camera& camera);

// Turns by the mouse (when looking), then moves: forward/back along the view
// direction, left/right along its horizontal right vector, up/down along world
// y. Diagonals are normalised, so every direction moves speed * dt.
void updateFlight(FreeFlight& flight, const FlightInput& input, float dt);

// The flight's position and direction (target one metre ahead) with the field
// of view and clip planes of lensFrom.
Camera cameraFromFlight(const FreeFlight& flight, const Camera& lensFrom);

} // namespace pf
