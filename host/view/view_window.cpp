#include "view/view_window.h"

#include <cstdlib>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "util/errors.h"
#include "util/printable.h"
#include "vk/check.h"

namespace vkp {
namespace {

std::string glfwErrorText() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? std::string("no error reported")
                                 : fmt::format("{} (GLFW error {:#x})", description ? description : "?", code);
}

}  // namespace

void requireDisplay() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0'))
        throw InputError("no display: DISPLAY is not set, and `vkphoton view` needs a window (run it under X11, or "
                         "xvfb-run -a vkphoton view ...); for images without a display use `vkphoton render`");
}

ViewWindow::ViewWindow(uint32_t width, uint32_t height, const std::string& title) : m_width(width), m_height(height) {
    glfwInitHint(GLFW_JOYSTICK_HAT_BUTTONS, GLFW_FALSE);
    if (!glfwInit())
        throw InputError(fmt::format("cannot open the display (DISPLAY={}): {}; for images without a window use "
                                     "`vkphoton render`",
                                     printable(std::getenv("DISPLAY") ? std::getenv("DISPLAY") : ""), glfwErrorText()));
    if (!glfwVulkanSupported()) {
        const std::string why = glfwErrorText();
        glfwTerminate();
        throw InputError(fmt::format("the display offers no Vulkan presentation: {}", why));
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    m_window = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!m_window) {
        const std::string why = glfwErrorText();
        glfwTerminate();
        throw InputError(fmt::format("cannot open a {}x{} window: {}", width, height, why));
    }
    glfwSetWindowUserPointer(m_window, this);
    glfwSetKeyCallback(m_window, &ViewWindow::onKey);
    glfwSetMouseButtonCallback(m_window, &ViewWindow::onButton);
    glfwSetCursorPosCallback(m_window, &ViewWindow::onCursor);
    glfwSetScrollCallback(m_window, &ViewWindow::onScroll);
    glfwSetFramebufferSizeCallback(m_window, &ViewWindow::onFramebufferSize);
}

ViewWindow::~ViewWindow() {
    if (m_window) glfwDestroyWindow(m_window);
    glfwTerminate();
}

std::vector<std::string> ViewWindow::requiredInstanceExtensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw InputError(fmt::format("the display offers no Vulkan presentation: {}", glfwErrorText()));
    return std::vector<std::string>(names, names + count);
}

bool ViewWindow::canPresent(VkInstance instance, VkPhysicalDevice device, uint32_t queueFamily) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, queueFamily) == GLFW_TRUE;
}

VkSurfaceKHR ViewWindow::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vk::check(glfwCreateWindowSurface(instance, m_window, nullptr, &surface), "creating the window's surface");
    return surface;
}

std::vector<ViewAction> ViewWindow::poll() {
    glfwPollEvents();
    std::vector<ViewAction> actions;
    actions.swap(m_actions);
    return actions;
}

bool ViewWindow::closeRequested() const { return glfwWindowShouldClose(m_window); }

void ViewWindow::setTitle(const std::string& title) { glfwSetWindowTitle(m_window, title.c_str()); }

void ViewWindow::resize(uint32_t width, uint32_t height) { glfwSetWindowSize(m_window, int(width), int(height)); }

void ViewWindow::onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(window));
    ViewAction a;
    a.kind = ViewAction::Kind::Key;
    switch (key) {
    case GLFW_KEY_I: a.key = ViewKey::Integrator; break;
    case GLFW_KEY_R: a.key = ViewKey::Restart; break;
    case GLFW_KEY_S: a.key = ViewKey::Screenshot; break;
    case GLFW_KEY_SPACE: a.key = ViewKey::PlayPause; break;
    case GLFW_KEY_H: a.key = ViewKey::Help; break;
    case GLFW_KEY_Q:
    case GLFW_KEY_ESCAPE: a.key = ViewKey::Quit; break;
    default: return;
    }
    self->m_actions.push_back(a);
}

void ViewWindow::onButton(GLFWwindow* window, int button, int action, int mods) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(window));
    if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
    if (action == GLFW_PRESS && self->m_dragButton < 0) {
        self->m_dragButton = button;
        self->m_dragShift = (mods & GLFW_MOD_SHIFT) != 0;
        self->m_dragged = false;
        self->m_pressAt = self->m_cursor;
    } else if (action == GLFW_RELEASE && button == self->m_dragButton) {
        if (!self->m_dragged && button == GLFW_MOUSE_BUTTON_LEFT) {
            ViewAction a;
            a.kind = ViewAction::Kind::Select;
            a.a = self->m_pressAt;
            self->m_actions.push_back(a);
        }
        self->m_dragButton = -1;
    }
}

void ViewWindow::onCursor(GLFWwindow* window, double x, double y) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(window));
    const glm::vec2 at{float(x), float(y)};
    const glm::vec2 last = self->m_cursor;
    self->m_cursor = at;
    if (self->m_dragButton < 0) return;
    if (!self->m_dragged) {
        if (glm::length(at - self->m_pressAt) < kClickSlopPixels) return;
        self->m_dragged = true;
    }
    const DragButton button = self->m_dragButton == GLFW_MOUSE_BUTTON_RIGHT ? DragButton::Right
                              : self->m_dragShift                         ? DragButton::ShiftLeft
                                                                          : DragButton::Left;
    self->m_actions.push_back(dragAction(button, last, at));
}

void ViewWindow::onScroll(GLFWwindow* window, double, double dy) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(window));
    ViewAction a;
    a.kind = ViewAction::Kind::Dolly;
    a.amount = float(dy);
    self->m_actions.push_back(a);
}

// A minimised window (0 x 0) keeps its last size: nothing is shown until it comes back.
void ViewWindow::onFramebufferSize(GLFWwindow* window, int width, int height) {
    auto* self = static_cast<ViewWindow*>(glfwGetWindowUserPointer(window));
    if (width <= 0 || height <= 0 || (uint32_t(width) == self->m_width && uint32_t(height) == self->m_height)) return;
    self->m_width = uint32_t(width);
    self->m_height = uint32_t(height);
    ViewAction a;
    a.kind = ViewAction::Kind::Resize;
    a.a = {float(width), float(height)};
    self->m_actions.push_back(a);
}

}  // namespace vkp
