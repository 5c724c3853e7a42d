#include "engine/window/window_input.h"

#include <GLFW/glfw3.h>

namespace pf {
namespace {

bool keyDown(GLFWwindow* window, int key) { return glfwGetKey(window, key) == GLFW_PRESS; }

bool buttonDown(GLFWwindow* window, int button) { return glfwGetMouseButton(window, button) == GLFW_PRESS; }

} // namespace

WindowInput pollWindowInput(GLFWwindow* window, WindowInputState& state) {
    if (keyDown(window, GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window, GLFW_TRUE);

    WindowInput input;
    FlightInput& flight = input.flight;
    flight.forward = keyDown(window, GLFW_KEY_W);
    flight.back = keyDown(window, GLFW_KEY_S);
    flight.left = keyDown(window, GLFW_KEY_A);
    flight.right = keyDown(window, GLFW_KEY_D);
    flight.up = keyDown(window, GLFW_KEY_E) || keyDown(window, GLFW_KEY_SPACE);
    flight.down = keyDown(window, GLFW_KEY_Q) || keyDown(window, GLFW_KEY_LEFT_CONTROL);
    flight.fast = keyDown(window, GLFW_KEY_LEFT_SHIFT);
    flight.looking = buttonDown(window, GLFW_MOUSE_BUTTON_RIGHT) || buttonDown(window, GLFW_MOUSE_BUTTON_LEFT);

    // The cursor is tracked every frame, so the first frame of a drag does
    // not jump by everything the cursor did while no button was held.
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    if (flight.looking && state.cursorKnown) flight.mouseDelta = glm::vec2(cursor - state.lastCursor);
    state.lastCursor = cursor;
    state.cursorKnown = true;

    // A toggle fires on the press, not for every frame the key stays down.
    const bool pathKeyDown = keyDown(window, GLFW_KEY_P);
    input.togglePathPlayback = pathKeyDown && !state.pathKeyDown;
    state.pathKeyDown = pathKeyDown;
    return input;
}

} // namespace pf
