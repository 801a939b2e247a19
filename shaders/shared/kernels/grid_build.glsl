// Interface of the photon-grid build kernels: grid_count.comp, grid_scatter.comp,
// grid_sort_cells.comp and grid_copy.comp share one layout (shaders/photon/grid_build_bindings.glsl;
// host/photon/photon_grid.h).
#ifndef VKP_KERNELS_GRID_BUILD_GLSL
#define VKP_KERNELS_GRID_BUILD_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kGridGroupSize = 64u;

const uint kGridSlotBinding = 0u;         // GpuPhoton per input slot (empty slots are skipped)
const uint kGridCellStartBinding = 1u;    // uint per bucket, + 1: counts, then first sorted index
const uint kGridCursorBinding = 2u;       // uint per bucket: scatter positions
const uint kGridSortedSlotBinding = 3u;   // uint per grid photon: its input slot
const uint kGridPhotonBinding = 4u;       // GpuPhoton in bucket order
const uint kGridBindingCount = 5u;

SHARED_END

#ifdef __cplusplus
#include "shared/photon_grid.glsl"
namespace vkp::gpu {

struct GridCountKernel {
    static constexpr const char* kShader = "grid_count.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kGridBindingCount;
    static constexpr uint32_t kGroupSize = kGridGroupSize;
    using Push = PhotonGridParams;
};
struct GridScatterKernel {
    static constexpr const char* kShader = "grid_scatter.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kGridBindingCount;
    static constexpr uint32_t kGroupSize = kGridGroupSize;
    using Push = PhotonGridParams;
};
struct GridSortCellsKernel {
    static constexpr const char* kShader = "grid_sort_cells.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kGridBindingCount;
    static constexpr uint32_t kGroupSize = kGridGroupSize;
    using Push = PhotonGridParams;
};
struct GridCopyKernel {
    static constexpr const char* kShader = "grid_copy.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kGridBindingCount;
    static constexpr uint32_t kGroupSize = kGridGroupSize;
    using Push = PhotonGridParams;
};

}  // namespace vkp::gpu
#endif
#endif
