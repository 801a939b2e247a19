// Interface of the photon compaction kernels: compact_mark.comp, compact_scatter.comp and
// compact_advance.comp share one layout (shaders/photon/compact.glsl; host/photon/photon_compaction.h).
#ifndef VKP_KERNELS_COMPACTION_GLSL
#define VKP_KERNELS_COMPACTION_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kCompactGroupSize = 64u;    // compact_mark.comp, compact_scatter.comp
const uint kCompactAdvanceGroupSize = 1u;  // compact_advance.comp: one invocation

const uint kCompactSlotBinding = 0u;   // GpuPhoton per traced slot (read)
const uint kCompactRankBinding = 1u;   // uint per slot, + 1: marks, then (scanned) ranks
const uint kCompactMapBinding = 2u;    // GpuPhoton: the dense map, appended to
const uint kCompactStateBinding = 3u;  // uint[kPhotonMapStateSize]
const uint kCompactBindingCount = 4u;

// Slots of the map's state buffer.
const uint kPhotonMapStateCount = 0u;    // photons in the map
const uint kPhotonMapStateDropped = 1u;  // selected photons that did not fit (capacity)
const uint kPhotonMapStateSize = 4u;

SHARED_END

#ifdef __cplusplus
#include "shared/photon_grid.glsl"
namespace vkp::gpu {

struct CompactMarkKernel {
    static constexpr const char* kShader = "compact_mark.comp";
    static constexpr uint32_t kBindingCount = kCompactBindingCount;
    static constexpr uint32_t kGroupSize = kCompactGroupSize;
    using Push = PhotonCompactParams;
};
struct CompactScatterKernel {
    static constexpr const char* kShader = "compact_scatter.comp";
    static constexpr uint32_t kBindingCount = kCompactBindingCount;
    static constexpr uint32_t kGroupSize = kCompactGroupSize;
    using Push = PhotonCompactParams;
};
struct CompactAdvanceKernel {
    static constexpr const char* kShader = "compact_advance.comp";
    static constexpr uint32_t kBindingCount = kCompactBindingCount;
    static constexpr uint32_t kGroupSize = kCompactAdvanceGroupSize;
    using Push = PhotonCompactParams;
};

}  // namespace vkp::gpu
#endif
#endif
