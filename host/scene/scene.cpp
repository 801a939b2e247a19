#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace vkp {

Camera defaultCamera(const Bounds& bounds) {
    constexpr float kYfov = 0.6981317f;  // 40 degrees
    constexpr float kMargin = 1.05f;     // 5% of air around the box
    Camera camera;
    camera.name = "default";
    camera.yfov = kYfov;
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const glm::vec3 half = bounds.empty() ? glm::vec3(0.5f) : 0.5f * bounds.extent();
    // Looking down -Z from center + (0, 0, d), a box corner (x, y, z) relative to the centre is
    // at depth d - z and must satisfy |x|, |y| <= (d - z) tan(yfov / 2): the vertical limit, and
    // the horizontal one for any aspect ratio >= 1. The nearest face's corners bind:
    // d = half.z + max(half.x, half.y) / tan(yfov / 2).
    const float tanHalf = std::tan(0.5f * kYfov);
    const float reach = std::max(std::max(half.x, half.y) * kMargin / tanHalf, 1e-3f);
    camera.position = center + glm::vec3(0.0f, 0.0f, half.z + reach);
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return camera;
}

}  // namespace vkp
