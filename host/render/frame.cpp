#include "render/frame.h"

#include <fmt/format.h>

#include "gpu_scene/scene_buffers.h"
#include "util/check_range.h"
#include "util/errors.h"

namespace vkp {

void FrameSettings::check() const {
    checkRange("--width", width, 1u, 16384u);
    checkRange("--height", height, 1u, 16384u);
    checkRange("--spp", samplesPerPixel, 1u, 1u << 24);
    checkRange("--max-depth", maxDepth, 1u, 1024u);
    checkRange("--time-limit", timeLimitSeconds, 0.0, 1.0e9);
    checkRange("--area-light-samples", areaLightSamples, 0u, 4096u);
    if (cameraIndex < -1) throw InputError(fmt::format("--camera {}: must be at least 0", cameraIndex));
}

Camera chooseCamera(const Scene& scene, int index) {
    if (index >= 0) {
        if (static_cast<size_t>(index) >= scene.cameras.size())
            throw InputError(fmt::format("--camera {}: the scene has {} camera(s)", index, scene.cameras.size()));
        return scene.cameras[index];
    }
    if (!scene.cameras.empty()) return scene.cameras.front();
    return defaultCamera(scene.bounds);
}

Frame makeFrame(const Scene& scene, const FrameSettings& settings) {
    Frame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    frame.seed = settings.seed;
    frame.maxDepth = settings.maxDepth;
    frame.nextEventEstimation = settings.nextEventEstimation;
    frame.pixelCentres = settings.pixelCentres;
    frame.camera = chooseCamera(scene, settings.cameraIndex);
    frame.gpuCamera = makeGpuCamera(frame.camera, settings.width, settings.height);
    return frame;
}

}  // namespace vkp
