// The renderer wires the passes together: scene upload, then progressive path-tracing batches
// into the film until the sample count, the time limit or a stop request is reached.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "image/image.h"
#include "passes/scene_buffers.h"
#include "scene/scene.h"

namespace vkp {
namespace vk { class Context; }

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    uint32_t seed = 0;
    uint32_t maxDepth = 16;           // path vertices after the camera
    double timeLimitSeconds = 0.0;    // 0: no limit
    int cameraIndex = -1;             // -1: the scene's first camera, or a default framing
    bool nextEventEstimation = true;  // false: BSDF sampling only (a reference for tests)
};

struct RenderProgress {
    uint32_t samplesDone = 0;
    uint32_t samplesTotal = 0;
    double elapsedSeconds = 0.0;
};

struct RenderStats {
    std::string device;
    uint64_t triangles = 0;
    uint64_t lights = 0;
    uint64_t gpuSceneBytes = 0;
    double bvhSeconds = 0.0;
    double uploadSeconds = 0.0;
    double renderSeconds = 0.0;
    uint32_t samplesPerPixel = 0;     // samples actually accumulated
    uint64_t nonFiniteSamples = 0;    // dropped samples that were NaN or infinite
    uint64_t cameraPaths = 0;
    bool partial = false;             // stopped before the requested sample count
    std::string stopReason;           // "complete", "time limit", "interrupted"
};

struct RenderResult {
    ImageRgb image;
    RenderStats stats;
};

using ProgressCallback = std::function<void(const RenderProgress&)>;

// Resolves --camera: the scene's camera `index`, the first one, or a default framing.
Camera chooseCamera(const Scene& scene, int index);

class Renderer {
public:
    Renderer(vk::Context& context, const Scene& scene);

    // Renders with the path tracer. `stop` (may be null) ends the render early after the
    // current batch; the image then holds the samples accumulated so far.
    RenderResult render(const RenderSettings& settings, const ProgressCallback& progress = {},
                        const std::atomic<bool>* stop = nullptr);

private:
    vk::Context& m_context;
    const Scene& m_scene;
    double m_uploadSeconds = 0.0;  // set while m_buffers is built: declared before it
    SceneArrays m_arrays;
    SceneBuffers m_buffers;
};

}  // namespace vkp
