// The viewer's camera: orbit about a look-at point (world +Y up), pan in the image plane, dolly
// towards the point. It starts from the camera `render` would use (--camera and --look-from /
// --look-at / --fov) and hands the view back as a ViewOverride, so the frame's camera is made the
// way `render --look-from X --look-at Y --fov F` makes it.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "render/frame.h"
#include "scene/scene.h"

namespace vkp {

class CameraController {
public:
    // `start`: the resolved camera; `pivot`: the point to orbit about (the scene's centre, moved
    // onto the view axis at its depth).
    CameraController(const Camera& start, glm::vec3 pivot);

    // Degrees: dx turns about +Y through the look-at point, dy changes the elevation (kept
    // within +-85 degrees of the horizon).
    void orbit(float dxDegrees, float dyDegrees);
    // Moves the camera and its look-at point so a point at the look-at depth follows the cursor
    // from `from` to `to` (window pixels, y down) in an image `height` pixels high.
    void pan(glm::vec2 from, glm::vec2 to, uint32_t height);
    // Towards the look-at point: the distance times kDollyPerNotch per notch (negative: away).
    void dolly(float notches);

    // The world-space translation that moves a point at `point`'s depth with the cursor from
    // `from` to `to`, in the plane through `point` parallel to the image.
    glm::vec3 imagePlaneDelta(glm::vec3 point, glm::vec2 from, glm::vec2 to, uint32_t height) const;

    // Whether the camera was changed since the start (orbit, pan or dolly).
    bool changed() const { return m_changed; }
    // The override that gives the current camera (`base` with look-from, look-at and fov set
    // once the camera was changed; `base` itself before).
    ViewOverride view(const ViewOverride& base) const;
    glm::vec3 position() const { return m_position; }
    glm::vec3 target() const { return m_target; }

private:
    glm::vec3 m_position;
    glm::vec3 m_target;
    float m_yfov;
    glm::vec3 m_forward, m_right, m_up;  // of the current camera
    bool m_changed = false;
    void updateFrame();
};

}  // namespace vkp
