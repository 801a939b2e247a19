// Interface of selective_mark.comp (host/photon/selective_mark_pass.h): a selective photon update's
// exact change detection. One invocation per stored path tests the path's track
// (shared/path_track.glsl) against the regions that changed since the last frame (the old and the
// new bounds of every moved instance) and the lights that moved; a path found is stale until it
// is retraced (its bit stays set), and every stale path gets its weight: how visible its change is.
#ifndef VKP_KERNELS_SELECTIVE_MARK_GLSL
#define VKP_KERNELS_SELECTIVE_MARK_GLSL
#include "shared/compat.glsl"
#include "shared/gpu_types.glsl"
SHARED_BEGIN

const uint kSelectiveMarkGroupSize = 64u;

const uint kSelectiveMarkTrackBinding = 0u;     // segmented: GpuPathTrack per path
const uint kSelectiveMarkSlotBinding = 1u;      // segmented: GpuPhoton per slot (path * maxDeposits + k)
const uint kSelectiveMarkRegionBinding = 2u;    // vec4 pairs: lower, upper corner of each changed region
const uint kSelectiveMarkLightBinding = 3u;     // uint bit mask over the lights: bit l set when light l changed
const uint kSelectiveMarkStaleBinding = 4u;     // uint bit mask over the paths: stale paths (read, or'ed)
const uint kSelectiveMarkWeightBinding = 5u;    // uint per path: its weight if stale (kSelectiveWeightScale), else untouched
const uint kSelectiveMarkCounterBinding = 6u;   // uint[kSelectiveMarkCounterCount]
const uint kSelectiveMarkBindingCount = 7u;

const uint kSelectiveMarkCounterStale = 0u;     // stale paths (found now or pending)
const uint kSelectiveMarkCounterFound = 1u;     // paths found stale by this dispatch
const uint kSelectiveMarkCounterCount = 4u;

// More changed regions than this are merged (host) into this many: a bound on each invocation's loops.
const uint kSelectiveMaxRegions = 256u;
// Fixed point of the paths' weights; a path's weight is clamped to 64.
const float kSelectiveWeightScale = 1024.0f;
const float kSelectiveMaxPathWeight = 64.0f;
// Weight of light outside the camera's view (the paper's visibility factor V, by frustum only).
const float kSelectiveOutOfView = 0.0625f;

struct SelectiveMarkParams {
    GpuCamera camera;        // the frame's camera: changes in its view weigh more
    uint pathCount;
    uint maxDeposits;
    uint regionCount;        // <= kSelectiveMaxRegions
    uint lightCount;         // lights the bit mask covers (0: no light changed)
    uint useCamera;          // 0: every change weighs as if in view
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(SelectiveMarkParams, 96)

// Whether p lies in the camera's view frustum (no occlusion test: the paper's view-frustum V).
INLINE bool inCameraView(GpuCamera c, vec3 p) {
    vec3 d = p - c.position;
    float z = dot(d, c.forward);
    if (z <= 0.0f) return false;
    float h = c.orthoHalfHeight > 0.0f ? c.orthoHalfHeight : z * c.tanHalfFovY;
    return abs(dot(d, c.up)) <= h && abs(dot(d, c.right)) <= h * c.aspect;
}

SHARED_END

#ifdef __cplusplus
namespace vkp::gpu {

struct SelectiveMarkKernel {
    static constexpr const char* kShader = "selective_mark.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M paths
    static constexpr uint32_t kBindingCount = kSelectiveMarkBindingCount;
    static constexpr uint32_t kGroupSize = kSelectiveMarkGroupSize;
    using Push = SelectiveMarkParams;
};

}  // namespace vkp::gpu
#endif
#endif
