#include "view/camera_controller.h"

#include <algorithm>
#include <cmath>

#include "view/view_input.h"

namespace vkp {
namespace {

constexpr float kMaxElevationDegrees = 85.0f;
const glm::vec3 kWorldUp(0.0f, 1.0f, 0.0f);

}  // namespace

CameraController::CameraController(const Camera& start, glm::vec3 pivot)
    : m_position(start.position), m_yfov(start.yfov), m_forward(start.forward), m_right(glm::normalize(glm::cross(start.forward, start.up))),
      m_up(start.up) {
    // The look-at point: the pivot's depth along the view axis (at least a small step ahead).
    const float depth = std::max(glm::dot(pivot - start.position, start.forward), 1e-3f * std::max(1.0f, glm::length(pivot)));
    m_target = start.position + depth * start.forward;
}

void CameraController::updateFrame() {
    m_forward = glm::normalize(m_target - m_position);
    glm::vec3 right = glm::cross(m_forward, kWorldUp);
    if (glm::length(right) < 1e-6f) right = m_right;  // looking straight up or down: keep the last right
    m_right = glm::normalize(right);
    m_up = glm::normalize(glm::cross(m_right, m_forward));
    m_changed = true;
}

void CameraController::orbit(float dxDegrees, float dyDegrees) {
    const glm::vec3 offset = m_position - m_target;
    const float distance = glm::length(offset);
    float azimuth = std::atan2(offset.x, offset.z);
    float elevation = std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f));
    azimuth -= glm::radians(dxDegrees);
    elevation = std::clamp(elevation + glm::radians(dyDegrees), -glm::radians(kMaxElevationDegrees),
                           glm::radians(kMaxElevationDegrees));
    m_position = m_target + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                                 std::cos(elevation) * std::cos(azimuth));
    updateFrame();
}

glm::vec3 CameraController::imagePlaneDelta(glm::vec3 point, glm::vec2 from, glm::vec2 to, uint32_t height) const {
    const float depth = std::max(glm::dot(point - m_position, m_forward), 1e-6f);
    const float worldPerPixel = 2.0f * std::tan(0.5f * m_yfov) * depth / float(std::max(1u, height));
    const glm::vec2 d = to - from;
    return worldPerPixel * (d.x * m_right - d.y * m_up);  // window y grows downwards
}

void CameraController::pan(glm::vec2 from, glm::vec2 to, uint32_t height) {
    // The scene follows the cursor: the camera moves the other way.
    const glm::vec3 delta = -imagePlaneDelta(m_target, from, to, height);
    m_position += delta;
    m_target += delta;
    updateFrame();
}

void CameraController::dolly(float notches) {
    const float distance = glm::length(m_position - m_target);
    const float next = std::max(distance * std::pow(kDollyPerNotch, notches), 1e-4f);
    m_position = m_target + (m_position - m_target) * (next / distance);
    updateFrame();
}

ViewOverride CameraController::view(const ViewOverride& base) const {
    if (!m_changed) return base;
    ViewOverride view = base;
    view.lookFrom = m_position;
    view.lookAt = m_target;
    view.fovDegrees = glm::degrees(m_yfov);
    return view;
}

}  // namespace vkp
