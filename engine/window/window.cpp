#include "engine/window/window.h"

#include "engine/vk/vk_check.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace pf {

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
    if (!glfwInit()) {
        const char* reason = nullptr;
        glfwGetError(&reason);
        throw std::runtime_error(std::string("cannot open a window: ") + (reason ? reason : "GLFW failed") +
                                 " (is DISPLAY set? use --capture for headless frames)");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("cannot open a window: GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " window");
    }
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) {
    VkSurfaceKHR surface;
    VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::pollEvents() const { glfwPollEvents(); }

void Window::waitEvents() const { glfwWaitEvents(); }

VkExtent2D Window::framebufferExtent() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(w), uint32_t(h)};
}

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

} // namespace pf
