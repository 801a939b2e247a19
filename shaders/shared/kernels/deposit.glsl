// Interface of the deposition kernels: photon_deposit.comp and deposit_redistribute.comp
// (host/photon/photon_deposit.h).
#ifndef VKP_KERNELS_DEPOSIT_GLSL
#define VKP_KERNELS_DEPOSIT_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kDepositGroupSize = 64u;

// photon_deposit.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kPhotonDepositGridBinding = kSceneBindingCount + 0u;            // the map's grid: cell starts, photons after it (photon_gather.glsl)
const uint kPhotonDepositSlotBinding = kSceneBindingCount + 2u;           // GpuPhoton per traced slot (kept, reweighted or cleared)
const uint kPhotonDepositImportanceBinding = kSceneBindingCount + 3u;     // vec2 per slot (importance_lookup.comp)
const uint kPhotonDepositRedistributedBinding = kSceneBindingCount + 4u;  // uint[3] per grid photon: power handed to it (fixed point)

// deposit_redistribute.comp
const uint kRedistributeMapBinding = 0u;            // GpuPhoton: the dense map
const uint kRedistributeSortedSlotBinding = 1u;     // uint per grid photon: its map slot
const uint kRedistributeRedistributedBinding = 2u;  // uint[3] per grid photon (added, then cleared)

SHARED_END

#ifdef __cplusplus
#include "shared/importance.glsl"
namespace vkp::gpu {

struct PhotonDepositKernel {
    static constexpr const char* kShader = "photon_deposit.comp";
    static constexpr uint32_t kBindingCount = kPhotonDepositRedistributedBinding + 1u;
    static constexpr uint32_t kGroupSize = kDepositGroupSize;
    using Push = PhotonDepositParams;
};
struct DepositRedistributeKernel {
    static constexpr const char* kShader = "deposit_redistribute.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kRedistributeRedistributedBinding + 1u;
    static constexpr uint32_t kGroupSize = kDepositGroupSize;
    using Push = RedistributeParams;
};

}  // namespace vkp::gpu
#endif
#endif
