// The viewer's window (GLFW, X11): opened without a client API so Vulkan presents to it,
// resizable (the image follows the window's size: a Resize action), and its mouse and keys turned
// into ViewActions (view/view_input.h): left drag orbits, right drag pans, the wheel dollies, a
// click selects, Shift+left drag moves the selected node.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "view/view_input.h"

struct GLFWwindow;

namespace vkp {

// Throws InputError (exit 2) unless $DISPLAY (or $WAYLAND_DISPLAY) is set: the message names
// DISPLAY and points to `vkphoton render` for images without a window.
void requireDisplay();

class ViewWindow {
public:
    // Initialises GLFW and opens a width x height window. Throws InputError when the display
    // cannot be opened or has no Vulkan presentation (GLFW's message included).
    ViewWindow(uint32_t width, uint32_t height, const std::string& title);
    ~ViewWindow();
    ViewWindow(const ViewWindow&) = delete;
    ViewWindow& operator=(const ViewWindow&) = delete;

    // The instance extensions presenting to the window needs, and whether a device's queue
    // family can present to it (for vk::ContextOptions).
    static std::vector<std::string> requiredInstanceExtensions();
    static bool canPresent(VkInstance instance, VkPhysicalDevice device, uint32_t queueFamily);

    VkSurfaceKHR createSurface(VkInstance instance) const;
    // Processes the window system's events; returns the actions they made since the last call
    // (drags arrive as the increments of each cursor move).
    std::vector<ViewAction> poll();
    bool closeRequested() const;
    void setTitle(const std::string& title);
    // Asks the window system for a width x height window (a script's `resize`); the Resize action
    // comes from its answer, as for a drag of the window's border.
    void resize(uint32_t width, uint32_t height);
    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onButton(GLFWwindow* window, int button, int action, int mods);
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onFramebufferSize(GLFWwindow* window, int width, int height);

    GLFWwindow* m_window = nullptr;
    uint32_t m_width, m_height;
    std::vector<ViewAction> m_actions;
    int m_dragButton = -1;          // GLFW button held, -1: none
    bool m_dragShift = false;
    bool m_dragged = false;         // moved beyond kClickSlopPixels since the press
    glm::vec2 m_pressAt{0.0f};
    glm::vec2 m_cursor{0.0f};
};

}  // namespace vkp
