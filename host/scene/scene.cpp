#include "scene/scene.h"

#include <cmath>

namespace vkp {

Camera defaultCamera(const Bounds& bounds) {
    Camera camera;
    camera.name = "default";
    camera.yfov = 0.6981317f;  // 40 degrees
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const glm::vec3 extent = bounds.empty() ? glm::vec3(1.0f) : bounds.extent();
    // Back off along +z until the bounding sphere fits the vertical field of view.
    const float radius = std::max(0.5f * glm::length(extent), 1e-3f);
    const float distance = radius / std::sin(0.5f * camera.yfov);
    camera.position = center + glm::vec3(0.0f, 0.0f, distance);
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return camera;
}

}  // namespace vkp
