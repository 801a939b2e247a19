// The renderer wires the passes together: scene upload, then progressive path-tracing batches
// into the film until the sample count, the time limit or a stop request is reached.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "image/image.h"
#include "gpu_scene/scene_buffers.h"
#include "scene/scene.h"

namespace vkp {
namespace vk { class Context; }

enum class Integrator {
    Path,    // path tracing with next-event estimation and MIS (the reference)
    Photon,  // two-pass photon mapping (render/photon_integrator.h)
    Guided,  // path tracing with photon-guided direction sampling (Jensen 1995)
};

// Settings of the guided path tracer (--integrator guided).
struct GuideRenderSettings {
    uint32_t photons = 100000;        // --guide-photons: paths traced for the guiding map
    uint32_t k = 50;                  // --guide-k nearest photons per grid
    uint32_t gridU = 4;               // --guide-grid MxN: m bands of theta ...
    uint32_t gridV = 16;              // ... by n sectors of phi (m * n <= 64)
    float mix = 0.5f;                 // --guide-mix: probability of sampling the grid (1: the paper's method)
    bool cache = true;                // --guide-cache: grids per cache cell and normal bin, built once
    uint32_t adaptPhotons = 0;        // --guide-adapt: coarsen cache grids to this many photons per cell (0: off)
    bool roulette = false;            // --guide-rr: Russian roulette by the guide's irradiance estimate
};

// Which traced photons the photon maps keep (--deposit; docs/importance-deposition.md).
enum class DepositMode {
    All,         // every photon (Jensen)
    Importance,  // kept with a probability from the camera's importance (Keller & Wald 2000)
    Density,     // kept until a required density is met (Suykens & Willems 2000)
};

// Settings of the photon integrator (--integrator photon).
struct PhotonRenderSettings {
    uint32_t globalPaths = 200000;    // --photons: paths traced for the global map (per pass when progressive)
    uint32_t causticPaths = 500000;   // --caustic-photons: paths traced for the caustic map (0: none)
    uint32_t gatherRays = 4;          // --gather-rays per sample; 0 reads the global map at the visible point
    uint32_t gatherK = 32;            // --gather-k nearest photons per global-map estimate
    uint32_t radiancePhotonStride = 4;  // --radiance-photons: every n-th global photon carries a
                                        // precomputed estimate for final gathers (0: estimate at every hit)
    float radius = 0.0f;              // --radius (world units); 0: 1.5 % of the scene's bounding radius
    float coneK = 1.1f;               // cone filter constant of the caustic estimate
    bool progressive = false;         // --progressive: SPPM, a fresh photon pass per sample
    float alpha = 0.7f;               // SPPM's fraction of new photons kept per pass
    uint32_t maxDeposits = 8;         // stored photons per global path at most
    DepositMode deposit = DepositMode::Importance;  // --deposit (docs/benchmarks.md: importance wins)
    float q = 0.0f;                   // --q: --photons paths fill the caustic map, the first q of them the
                                      // global map (Keller & Wald's N, q); 0: --caustic-photons paths
    uint32_t importonPaths = 1u << 16;  // --importons: camera paths of the importon pass
    float depositEpsilon = 0.01f;     // --deposit-epsilon: floor of the acceptance probability
    bool depositCutoff = false;       // --deposit-cutoff: drop photons below epsilon (biased)
    float densityAccuracy = 2.0e4f;   // --density-accuracy: required density per unit path importance
    uint32_t densityRounds = 8;       // --density-rounds
    bool densityRoulette = false;     // --density-roulette: weight kept photons instead of redistributing
};

// Who computes the direct light at the first path vertex (--direct).
enum class DirectLight {
    Traced,  // next-event estimation in the path tracer (the reference)
    Raster,  // stencil shadow volumes + lighting pass (host/passes/raster_direct_pass.h)
};

struct RenderSettings {
    Integrator integrator = Integrator::Path;
    PhotonRenderSettings photon;
    GuideRenderSettings guide;
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    uint32_t seed = 0;
    uint32_t maxDepth = 16;           // path vertices after the camera
    double timeLimitSeconds = 0.0;    // 0: no limit
    int cameraIndex = -1;             // -1: the scene's first camera, or a default framing
    bool nextEventEstimation = true;  // false: BSDF sampling only (a reference for tests)
    DirectLight direct = DirectLight::Traced;
    uint32_t areaLightSamples = 16;   // --area-light-samples: point samples per emissive triangle
                                      // for --direct raster (0: emissive triangles stay traced)
    bool pixelCentres = false;        // camera rays through pixel centres, no jitter (tests)
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
    std::string direct = "traced";    // --direct
    uint64_t rasterLights = 0;        // lights the raster pass covered (area samples count singly)
    double rasterSeconds = 0.0;       // raster direct light: shadow volumes, masks and lighting
    uint32_t samplesPerPixel = 0;     // samples actually accumulated
    uint64_t nonFiniteSamples = 0;    // dropped samples that were NaN or infinite
    uint64_t cameraPaths = 0;
    uint64_t pathSegments = 0;        // path tracers: rays traced from camera-path vertices (no shadow rays)
    bool partial = false;             // stopped before the requested sample count
    std::string integrator = "path";
    // Photon integrator only.
    uint64_t photonPathsTraced = 0;
    uint64_t globalPhotons = 0;       // in the global map (last pass when progressive)
    uint64_t causticPhotons = 0;
    uint64_t photonsDropped = 0;      // beyond a map's capacity
    uint64_t photonMapBytes = 0;      // stored photons and grid tables
    std::string deposit = "all";      // --deposit
    uint64_t globalCandidates = 0;    // photons the global paths deposited before the deposit decision
    uint64_t causticCandidates = 0;
    uint64_t importons = 0;           // stored by the importon pass
    uint64_t importonBytes = 0;       // the importons and their importance grid
    float importanceScale = 0.0f;     // Keller & Wald's f
    double photonSeconds = 0.0;       // tracing, compaction and grid builds
    float gatherRadius = 0.0f;        // caustic radius / initial SPPM radius, world units
    float globalRadius = 0.0f;        // largest k-nearest search radius in the global (or guiding) map
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

    // Renders with the chosen integrator. `stop` (may be null) ends the render early after the
    // current batch; the image then holds the samples accumulated so far.
    RenderResult render(const RenderSettings& settings, const ProgressCallback& progress = {},
                        const std::atomic<bool>* stop = nullptr);

private:
    RenderResult renderPath(const RenderSettings& settings, const ProgressCallback& progress,
                            const std::atomic<bool>* stop);
    void fillSceneStats(RenderStats& stats) const;

    vk::Context& m_context;
    const Scene& m_scene;
    double m_uploadSeconds = 0.0;  // set while m_buffers is built: declared before it
    SceneArrays m_arrays;
    SceneBuffers m_buffers;
};

}  // namespace vkp
