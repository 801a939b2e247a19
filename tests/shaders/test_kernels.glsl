// Interfaces of the test kernels in tests/shaders/, declared once for the shaders and the tests
// as shaders/shared/kernels/ does for the renderer's (bindings, push constants, workgroup size).
#ifndef VKP_TEST_KERNELS_GLSL
#define VKP_TEST_KERNELS_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
#include "shared/bsdf.glsl"
#include "shared/photon_grid.glsl"
SHARED_BEGIN

const uint kTestGroupSize = 64u;

// shared_functions_test.comp, the shader unit harness: evaluates one shared function for `count` inputs.
const uint kHarnessInputBinding = 0u;   // HarnessInput (shared/harness_functions.glsl)
const uint kHarnessOutputBinding = 1u;  // uvec4
const uint kHarnessTablesBinding = 2u;  // float: the BSDF's albedo tables (kBsdfTables)
struct HarnessParams {
    uint count;
    uint function;                      // kHarness* (shared/harness_functions.glsl)
};
STATIC_ASSERT_SIZE(HarnessParams, 8)

// light_selection_test.comp: the light sampler's shared functions (light_selection_harness.glsl).
const uint kLightTestInputBinding = 0u;      // LightHarnessInput
const uint kLightTestOutputBinding = 1u;     // LightHarnessOutput
const uint kLightTestSelectionBinding = 2u;  // float: the light-selection data (SceneArrays::lightCdf)
const uint kLightTestLightBinding = 3u;      // GpuLight
struct LightTestParams {
    uint count;
    uint lightCount;
};
STATIC_ASSERT_SIZE(LightTestParams, 8)

// bsdf_sampling_test.comp: sampleBsdf for one material and direction; push constants: uint count.
const uint kBsdfSamplingCaseBinding = 0u;     // BsdfSamplingCase
const uint kBsdfSamplingRandomBinding = 1u;   // vec4: the sample's random numbers (xyz)
const uint kBsdfSamplingOutputBinding = 2u;   // vec4: wi, 1 (0 when no lobe was sampled)
const uint kBsdfSamplingTablesBinding = 3u;   // float: the BSDF's albedo tables (kBsdfTables)
struct BsdfSamplingCase {
    BsdfParams bsdf;
    vec4 wo;                                  // xyz, in the shading frame
};
STATIC_ASSERT_SIZE(BsdfSamplingCase, 128)

// bvh_trace_test.comp; push constants: uint rayCount.
const uint kBvhTestRayBinding = 0u;       // TestRay
const uint kBvhTestNodeBinding = 1u;      // GpuBvhNode
const uint kBvhTestTriangleBinding = 2u;  // GpuTriangle, BVH order
const uint kBvhTestHitBinding = 3u;       // TestHit
const uint kBvhTestInstanceBinding = 4u;  // GpuInstanceHeader, GpuInstance[] (count 0: one tree)

// photon_gather_test.comp
const uint kGatherTestQueryBinding = 0u;    // GatherQuery
const uint kGatherTestFixedBinding = 1u;    // vec4 per query: fixed-radius sum, count
const uint kGatherTestNearestBinding = 2u;  // uint[kMaxGatherK + 2] per query
const uint kGatherTestGridBinding = 3u;     // the grid's cell starts, photons at 4 (photon_gather.glsl)
const uint kGatherTestBsdfBinding = 5u;     // one BsdfParams (larger than push constants allow beside the rest)
struct GatherTestParams {
    PhotonGridView grid;
    uint count;
    float coneK;
    uint requiredFlags;
    uint rejectedFlags;
};
STATIC_ASSERT_SIZE(GatherTestParams, 32)

// shadow_visibility_test.comp: the scene's bindings, then; push constants: RasterDirectParams.
const uint kShadowTestLightBinding = kSceneBindingCount + 0u;  // GpuLight: the raster lights
const uint kShadowTestOutputBinding = kSceneBindingCount + 1u;  // uint[3] per pixel

// kernel_interface_test.comp: outputs[i] = inputs[i] * scale + offset.
const uint kInterfaceTestInputBinding = 0u;
const uint kInterfaceTestOutputBinding = 1u;
struct InterfaceTestParams {
    uint count;
    uint scale;
    uint offset;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(InterfaceTestParams, 24)

// constant_film.comp, the toy integrator of tests/render/integrator_seam_render_test.cpp: adds sampleCount
// samples of `radiance` to each of `pixels` film entries (vec4: RGB sum, sample count).
const uint kConstantFilmBinding = 0u;
struct ConstantFilmParams {
    vec4 radiance;
    uint pixels;
    uint sampleCount;
    uint pad0;
    uint pad1;
};
STATIC_ASSERT_SIZE(ConstantFilmParams, 32)

// segmented_test.comp: reads elements [0, count) of a segmented array of uints through UINT_AT,
// writes each to outputs[1 + i] and stores it back plus one; outputs[0] = the kSingleSegment the
// dispatch was compiled with (shaders/common/segmented_arrays.glsl).
const uint kSegmentedTestArrayBinding = 0u;
const uint kSegmentedTestOutputBinding = 1u;
struct SegmentedTestParams {
    uint count;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(SegmentedTestParams, 16)

SHARED_END

#ifdef __cplusplus
#include "shared/shadow_volume.glsl"
namespace vkp::gpu {

struct HarnessKernel {
    static constexpr const char* kShader = "shared_functions_test.comp";
    static constexpr uint32_t kBindingCount = kHarnessTablesBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = HarnessParams;
};
struct LightTestKernel {
    static constexpr const char* kShader = "light_selection_test.comp";
    static constexpr uint32_t kBindingCount = kLightTestLightBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = LightTestParams;
};
struct BsdfSamplingKernel {
    static constexpr const char* kShader = "bsdf_sampling_test.comp";
    static constexpr uint32_t kBindingCount = kBsdfSamplingTablesBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = uint32_t;
};
struct BvhTestKernel {
    static constexpr const char* kShader = "bvh_trace_test.comp";
    static constexpr uint32_t kBindingCount = kBvhTestInstanceBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = uint32_t;
};
struct GatherTestKernel {
    static constexpr const char* kShader = "photon_gather_test.comp";
    static constexpr uint32_t kBindingCount = kGatherTestBsdfBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = GatherTestParams;
};
struct ShadowTestKernel {
    static constexpr const char* kShader = "shadow_visibility_test.comp";
    static constexpr uint32_t kBindingCount = kShadowTestOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = RasterDirectParams;
};
struct InterfaceTestKernel {
    static constexpr const char* kShader = "kernel_interface_test.comp";
    static constexpr uint32_t kBindingCount = kInterfaceTestOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = InterfaceTestParams;
};
struct SegmentedTestKernel {
    static constexpr const char* kShader = "segmented_test.comp";
    static constexpr uint32_t kBindingCount = kSegmentedTestOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = SegmentedTestParams;
};
struct ConstantFilmKernel {
    static constexpr const char* kShader = "constant_film.comp";
    static constexpr uint32_t kBindingCount = kConstantFilmBinding + 1u;
    static constexpr uint32_t kGroupSize = kTestGroupSize;
    using Push = ConstantFilmParams;
};

}  // namespace vkp::gpu
#endif
#endif
