// Interface of the importon kernels: importon_trace.comp, importance_splat.comp,
// importance_lookup.comp and importon_importance.comp (host/photon/importon_trace_pass.h,
// importance_splat_pass.h, importance_lookup_pass.h).
#ifndef VKP_KERNELS_IMPORTONS_GLSL
#define VKP_KERNELS_IMPORTONS_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kImportonGroupSize = 64u;

// importon_trace.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kImportonTraceImportonBinding = kSceneBindingCount + 0u;   // GpuImporton per slot: path * maxDeposits + k

// importance_splat.comp
const uint kImportanceSplatImportonBinding = 0u; // GpuImporton per slot (read)
const uint kImportanceSplatTableBinding = 1u;    // ImportanceCell (zeroed before, summed into)

// importance_lookup.comp (photon slots) and importon_importance.comp (importon slots)
const uint kImportanceLookupTableBinding = 0u;      // ImportanceCell
const uint kImportanceLookupSlotBinding = 1u;       // GpuPhoton or GpuImporton per slot
const uint kImportanceLookupImportanceBinding = 2u; // vec2 per slot: density, largest path importance

SHARED_END

#ifdef __cplusplus
#include "shared/importance.glsl"
namespace vkp::gpu {

struct ImportonTraceKernel {
    static constexpr const char* kShader = "importon_trace.comp";
    static constexpr uint32_t kBindingCount = kImportonTraceImportonBinding + 1u;
    static constexpr uint32_t kGroupSize = kImportonGroupSize;
    using Push = ImportonTraceParams;
};
struct ImportanceSplatKernel {
    static constexpr const char* kShader = "importance_splat.comp";
    static constexpr uint32_t kBindingCount = kImportanceSplatTableBinding + 1u;
    static constexpr uint32_t kGroupSize = kImportonGroupSize;
    using Push = ImportanceGridParams;
};
struct ImportanceLookupKernel {
    static constexpr const char* kShader = "importance_lookup.comp";
    static constexpr uint32_t kBindingCount = kImportanceLookupImportanceBinding + 1u;
    static constexpr uint32_t kGroupSize = kImportonGroupSize;
    using Push = ImportanceGridParams;
};
struct ImportonImportanceKernel {
    static constexpr const char* kShader = "importon_importance.comp";
    static constexpr uint32_t kBindingCount = kImportanceLookupImportanceBinding + 1u;
    static constexpr uint32_t kGroupSize = kImportonGroupSize;
    using Push = ImportanceGridParams;
};

}  // namespace vkp::gpu
#endif
#endif
