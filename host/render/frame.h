// What one render looks at and how it samples, set by the user (FrameSettings) and resolved once
// per render into a Frame that every integrator reads: the camera, the image size, the seed, the
// camera paths' depth and who computes the first vertex's direct light (--direct).
#pragma once

#include <cstdint>
#include <optional>

#include "render/crop_window.h"
#include "render/render_control.h"
#include "scene/scene.h"
#include "shared/gpu_types.glsl"

namespace vkp {
namespace vk { class Buffer; }
class PhotonMapUpdate;  // photon/photon_map_update.h: an animation's photon-map update

// Which frame of a sequence is being rendered.
struct FrameUpdateInfo {
    uint32_t frame = 0;       // the frame number (--frames FIRST:LAST)
    double time = 0.0;        // seconds: frame / fps
    bool firstFrame = true;   // the first frame of the sequence (or a still render)
    uint64_t sceneGeneration = 0;  // changes when the frames loop rebuilt the scene (new buffers)
    const gpu::GpuCamera* camera = nullptr;  // the frame's view (set by buildFramePhotonMap): what is visible first
    // false: nothing in the scene moved since the last build (`vkphoton view` after a camera
    // move): a selective update reuses its persistent paths as they are and traces none.
    bool retrace = true;
};

// Who computes the direct light at the first path vertex (--direct).
enum class DirectLight {
    Traced,  // next-event estimation in the camera-path shaders (the reference)
    Raster,  // stencil shadow volumes + lighting pass (render/raster_direct.h)
};

// --look-from, --look-at, --fov: changes to whichever camera --camera picks (a file camera or
// the default framing). --look-from alone looks at the centre of the scene's bounds; --look-at
// alone turns the camera where it stands; --fov alone keeps position and direction.
struct ViewOverride {
    std::optional<glm::vec3> lookFrom;   // world position
    std::optional<glm::vec3> lookAt;     // world position
    std::optional<float> fovDegrees;     // vertical field of view, (0, 180)

    bool empty() const { return !lookFrom && !lookAt && !fovDegrees; }
    // Throws InputError naming the flag: coordinates not finite, --look-from equal to
    // --look-at, a field of view outside (0, 180) degrees or NaN.
    void check() const;
};

// The largest image side `--width`, `--height` and the viewer's resize accept.
inline constexpr uint32_t kMaxImageSide = 16384;

struct FrameSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    uint32_t seed = 0;
    uint32_t maxDepth = 16;           // path vertices after the camera (path tracers)
    double timeLimitSeconds = 0.0;    // 0: no limit
    int cameraIndex = -1;             // -1: the scene's first camera, or a default framing
    ViewOverride view;                // --look-from, --look-at, --fov
    bool nextEventEstimation = true;  // false: BSDF sampling only (a reference for tests)
    DirectLight direct = DirectLight::Traced;
    uint32_t areaLightSamples = 16;   // --area-light-samples: point samples per emissive triangle
                                      // for --direct raster (0: emissive triangles stay traced)
    bool pixelCentres = false;        // camera rays through pixel centres, no jitter (tests)
    // When --time-limit starts counting: the command's start (so loading and the photon passes
    // count); unset, the call to Renderer::render.
    std::optional<Clock::time_point> timeLimitFrom;
    // --crop / --tile: render only this window of the width x height frame (render/crop_window.h).
    std::optional<CropWindow> crop;
    // --frames: the sequence's photon-map update (photon/photon_map_update.h) and which frame this
    // is; null: a still render (the maps are built by PhotonMap::build).
    PhotonMapUpdate* photonUpdate = nullptr;
    FrameUpdateInfo update;

    // Throws InputError naming the flag of a value out of range.
    void check() const;
};

// A three-quarter view of `bounds` from the +X, +Y, +Z side (azimuth 45 degrees between +X and
// +Z, elevation 30 degrees, up +Y) looking at the box's centre, with a vertical field of view of
// `yfovRadians`, at the least distance where all eight corners project inside the central
// kFramingFill of an image of aspect `aspect` (width / height), horizontally and vertically.
// An empty box frames the unit cube at the origin; a box with no extent frames a cube of size
// 1e-3 * max(1, |centre|) around it.
inline constexpr float kFramingFill = 0.95f;
inline constexpr float kFramingYfov = 0.6981317f;  // 40 degrees
Camera framingCamera(const Bounds& bounds, float aspect, float yfovRadians = kFramingYfov);

// Resolves --camera and the view override: the scene's camera `index`, else its first camera,
// else framingCamera(scene.bounds, aspect) (at 40 degrees, or --fov's field of view), and then
// `view` on top. Throws InputError for an index the scene does not have, or for an override
// that leaves the camera where it looks.
Camera chooseCamera(const Scene& scene, int index, float aspect = 1.0f, const ViewOverride& view = {});

// A frame as the integrators see it.
struct Frame {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t seed = 0;
    uint32_t maxDepth = 0;
    bool nextEventEstimation = true;
    Camera camera;
    gpu::GpuCamera gpuCamera{};
    // --direct raster: per-pixel direct light of the covered lights (vec4 RGB) and the
    // kPathFlagRaster* flags saying which; with --direct traced a placeholder and no flags.
    const vk::Buffer* rasterDirect = nullptr;
    uint32_t rasterFlags = 0;
    bool pixelCentres = false;
    RenderControl control;  // the stop flag and the deadline: long phases check it between chunks
    std::optional<CropWindow> crop;  // --crop / --tile: the window the camera passes compute
    PhotonMapUpdate* photonUpdate = nullptr;  // --frames: how photon maps are (re)built (photon/photon_map_update.h)
    FrameUpdateInfo update;               // which frame of the sequence

    uint64_t pixels() const { return uint64_t(width) * height; }
    // The pixel indices the camera passes compute: the crop window's rows, else every pixel.
    vk::ItemRange pixelRange() const { return crop ? cropPixels(*crop, width) : vk::ItemRange{0, pixels()}; }
    // The kPathFlag* bits every camera-path shader takes: raster coverage and pixel centres.
    uint32_t cameraPathFlags() const { return rasterFlags | (pixelCentres ? gpu::kPathFlagPixelCentres : 0u); }
};

// The frame of `settings` with its camera resolved and no raster direct light (the driver adds
// it): what `vkphoton photons` and tools share with renders.
Frame makeFrame(const Scene& scene, const FrameSettings& settings);

}  // namespace vkp
