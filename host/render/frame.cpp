#include "render/frame.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "gpu_scene/scene_buffers.h"
#include "util/check_range.h"
#include "util/errors.h"

namespace vkp {
namespace {

constexpr double kFramingAzimuth = 0.7853981633974483;    // 45 degrees from +Z towards +X
constexpr double kFramingElevation = 0.5235987755982988;  // 30 degrees above the horizon

void checkPoint(std::string_view flag, const std::optional<glm::vec3>& p) {
    if (p && !(std::isfinite(p->x) && std::isfinite(p->y) && std::isfinite(p->z)))
        throw InputError(fmt::format("{} {},{},{}: every coordinate must be a finite number", flag, p->x, p->y, p->z));
}

// Unit forward and up for a camera at `from` looking at `at`: up is +Y made orthogonal, or -Z /
// +Z when looking straight down / up (so that +X stays to the right).
void aim(Camera& camera, glm::vec3 from, glm::vec3 at) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(at) - glm::dvec3(from));
    const glm::dvec3 worldUp = std::abs(forward.y) < 0.9999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, forward.y < 0 ? -1 : 1);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, worldUp));
    camera.position = from;
    camera.forward = glm::vec3(forward);
    camera.up = glm::vec3(glm::cross(right, forward));
}

}  // namespace

void ViewOverride::check() const {
    checkPoint("--look-from", lookFrom);
    checkPoint("--look-at", lookAt);
    if (lookFrom && lookAt && *lookFrom == *lookAt)
        throw InputError(fmt::format("--look-from and --look-at: both are ({}, {}, {}); the camera needs a direction",
                                     lookAt->x, lookAt->y, lookAt->z));
    if (fovDegrees && !(*fovDegrees > 0.0f && *fovDegrees < 180.0f))
        throw InputError(fmt::format("--fov {}: the vertical field of view must be more than 0 and less than 180 degrees",
                                     *fovDegrees));
}

Camera framingCamera(const Bounds& bounds, float aspect, float yfovRadians) {
    const glm::dvec3 center = bounds.empty() ? glm::dvec3(0.0) : glm::dvec3(bounds.center());
    glm::dvec3 half = bounds.empty() ? glm::dvec3(0.5) : 0.5 * glm::dvec3(bounds.extent());
    if (half == glm::dvec3(0.0)) half = glm::dvec3(0.5e-3 * std::max(1.0, glm::length(center)));
    const glm::dvec3 toCamera(std::cos(kFramingElevation) * std::sin(kFramingAzimuth), std::sin(kFramingElevation),
                              std::cos(kFramingElevation) * std::cos(kFramingAzimuth));
    const glm::dvec3 forward = -toCamera;
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    // A corner q (relative to the centre) seen from centre + d * toCamera lies at depth
    // d - q.toCamera and projects inside the image when |q.right| <= depth * tanH and
    // |q.up| <= depth * tanV: each corner gives a least distance, the largest one binds. A
    // camera farther back sees every corner nearer the middle, so the rest stay inside too.
    const double tanV = std::tan(0.5 * double(yfovRadians)) * kFramingFill;
    const double tanH = tanV * std::max(double(aspect), 1e-6);
    double distance = 0.0, nearest = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 q((corner & 1 ? 1 : -1) * half.x, (corner & 2 ? 1 : -1) * half.y, (corner & 4 ? 1 : -1) * half.z);
        const double along = glm::dot(q, toCamera);
        distance = std::max(distance, along + std::max(std::abs(glm::dot(q, right)) / tanH, std::abs(glm::dot(q, up)) / tanV));
        nearest = std::max(nearest, along);
    }
    // Never closer than 1 % of the box's half-diagonal in front of its nearest corner.
    distance = std::max(distance, nearest + 0.01 * glm::length(half));
    Camera camera;
    camera.name = "framing";
    camera.yfov = yfovRadians;
    camera.position = glm::vec3(center + distance * toCamera);
    camera.forward = glm::vec3(forward);
    camera.up = glm::vec3(up);
    return camera;
}

void FrameSettings::check() const {
    checkRange("--width", width, 1u, kMaxImageSide);
    checkRange("--height", height, 1u, kMaxImageSide);
    checkRange("--spp", samplesPerPixel, 1u, 1u << 24);
    checkRange("--max-depth", maxDepth, 1u, 1024u);
    checkRange("--time-limit", timeLimitSeconds, 0.0, 1.0e9);
    checkRange("--area-light-samples", areaLightSamples, 0u, 4096u);
    if (cameraIndex < -1) throw InputError(fmt::format("--camera {}: must be at least 0", cameraIndex));
    view.check();
    if (crop) checkCrop(*crop, width, height);
}

Camera chooseCamera(const Scene& scene, int index, float aspect, const ViewOverride& view) {
    if (index >= 0 && static_cast<size_t>(index) >= scene.cameras.size())
        throw InputError(fmt::format("--camera {}: the scene has {} camera(s)", index, scene.cameras.size()));
    const float yfov = view.fovDegrees ? glm::radians(*view.fovDegrees) : kFramingYfov;
    Camera camera = index >= 0            ? scene.cameras[index]
                    : !scene.cameras.empty() ? scene.cameras.front()
                                            : framingCamera(scene.bounds, aspect, yfov);
    camera.yfov = view.fovDegrees ? yfov : camera.yfov;
    if (view.fovDegrees) camera.orthoHalfHeight = 0.0f;  // --fov: a pinhole camera
    if (view.lookFrom || view.lookAt) {
        const glm::vec3 from = view.lookFrom.value_or(camera.position);
        const glm::vec3 at = view.lookAt ? *view.lookAt : scene.bounds.empty() ? glm::vec3(0.0f) : scene.bounds.center();
        if (!(glm::length(glm::dvec3(at) - glm::dvec3(from)) > 0.0))
            throw InputError(fmt::format("{}: the camera would stand at ({}, {}, {}), the point it looks at",
                                         view.lookAt ? "--look-at" : "--look-from", at.x, at.y, at.z));
        aim(camera, from, at);
    }
    return camera;
}

Frame makeFrame(const Scene& scene, const FrameSettings& settings) {
    Frame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    frame.seed = settings.seed;
    frame.maxDepth = settings.maxDepth;
    frame.nextEventEstimation = settings.nextEventEstimation;
    frame.pixelCentres = settings.pixelCentres;
    frame.crop = settings.crop;
    frame.photonUpdate = settings.photonUpdate;
    frame.update = settings.update;
    frame.camera = chooseCamera(scene, settings.cameraIndex, float(settings.width) / float(settings.height), settings.view);
    frame.gpuCamera = makeGpuCamera(frame.camera, settings.width, settings.height);
    frame.gpuCamera.pixelSamples = settings.samplesPerPixel;
    return frame;
}

}  // namespace vkp
