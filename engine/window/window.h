// A GLFW window with a Vulkan surface.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

struct GLFWwindow;

namespace pf {

class Window {
public:
    // Throws when no display can be opened (e.g. DISPLAY unset).
    Window(uint32_t width, uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // The instance extensions the surface needs; valid after construction.
    static std::vector<std::string> requiredInstanceExtensions();

    VkSurfaceKHR createSurface(VkInstance instance);
    bool shouldClose() const;
    void requestClose(); // as the close button does: shouldClose() from now on
    void pollEvents() const;
    void waitEvents() const; // blocks until something happens, e.g. while minimised
    VkExtent2D framebufferExtent() const;
    void setTitle(const std::string& title);
    GLFWwindow* handle() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace pf
