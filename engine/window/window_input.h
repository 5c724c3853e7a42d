// Keyboard and mouse of a GLFW window turned into flight input and toggles.
// Polled once a frame after Window::pollEvents():
//   W/S forward/back, A/D left/right, E or Space up, Q or Left Ctrl down,
//   Left Shift fast; hold the right or left mouse button and move to look;
//   P toggles camera-path playback vs free flight; Escape closes the window.
#pragma once

#include "engine/window/free_flight.h"

#include <glm/glm.hpp>

struct GLFWwindow;

namespace pf {

// What pollWindowInput() remembers between frames.
struct WindowInputState {
    glm::dvec2 lastCursor{0.0};
    bool cursorKnown = false; // lastCursor holds a real position
    bool pathKeyDown = false; // P was held at the last poll
};

struct WindowInput {
    FlightInput flight;
    bool togglePathPlayback = false; // P went down since the last poll
};

// Reads the keys and cursor; Escape sets the window's close flag.
WindowInput pollWindowInput(GLFWwindow* window, WindowInputState& state);

} // namespace pf
