// Interface of photon_trace.comp (host/photon/photon_trace_pass.h).
#ifndef VKP_KERNELS_PHOTON_TRACE_GLSL
#define VKP_KERNELS_PHOTON_TRACE_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kPhotonTraceGroupSize = 64u;

// Bindings after the scene's (0 .. kSceneBindingCount - 1).
const uint kPhotonTracePhotonBinding = kSceneBindingCount + 0u;   // GpuPhoton per slot: (path - firstPath) * maxDeposits + k
const uint kPhotonTraceCounterBinding = kSceneBindingCount + 1u;  // uint[kPhotonCounterCount]
const uint kPhotonTracePathListBinding = kSceneBindingCount + 2u; // uint per path: Halton offset (PhotonTraceParams.pathList)
const uint kPhotonTraceTrackBinding = kSceneBindingCount + 3u;    // GpuPathTrack per path (PhotonTraceParams.trackPaths)

// Slots of the counter buffer.
const uint kPhotonCounterStoredCaustic = 0u;
const uint kPhotonCounterStoredGlobal = 1u;    // after at least one diffuse/glossy bounce
const uint kPhotonCounterStoredPrimary = 2u;   // direct (first-hit) photons
const uint kPhotonCounterAbsorbed = 3u;        // paths ended by Russian roulette or a black surface
const uint kPhotonCounterLost = 4u;            // paths that left the scene
const uint kPhotonCounterTruncated = 5u;       // paths cut short: kPhotonMaxBounces (or lavapipe's loop
                                               // budget), or a map of one kind whose photons the path can no longer make
const uint kPhotonCounterSampled = 6u;         // paths with more deposits than maxDeposits slots: their
                                               // slots hold a uniform sample of them (reservoir), reweighted
const uint kPhotonCounterCount = 8u;
// Bounces a photon path takes at most; a path still going then is counted as truncated and as a
// silent termination (shared/kernels/terminations.glsl).
const uint kPhotonMaxBounces = 64u;

SHARED_END

#ifdef __cplusplus
#include "shared/photon.glsl"
namespace vkp::gpu {

struct PhotonTraceKernel {
    static constexpr const char* kShader = "photon_trace.comp";
    static constexpr uint32_t kBindingCount = kPhotonTraceTrackBinding + 1u;
    static constexpr uint32_t kGroupSize = kPhotonTraceGroupSize;
    using Push = PhotonTraceParams;
};

}  // namespace vkp::gpu
#endif
#endif
