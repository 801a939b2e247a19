// The host<->shader contract (shaders/shared/kernels/, host/vk/kernel.h): every kernel's interface
// agrees with its shader's SPIR-V, and a kernel told an interface its shader does not declare
// fails when it is created, with a message naming the shader and the difference.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "shaders/test_kernels.glsl"
#include "shared/kernels/aov.glsl"
#include "shared/kernels/compaction.glsl"
#include "shared/kernels/deposit.glsl"
#include "shared/kernels/grid_build.glsl"
#include "shared/kernels/guide_cache.glsl"
#include "shared/kernels/guide_learn.glsl"
#include "shared/kernels/importons.glsl"
#include "shared/kernels/path_trace.glsl"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/kernels/photon_trace.glsl"
#include "shared/kernels/prefix_scan.glsl"
#include "shared/kernels/raster_direct.glsl"
#include "shared/kernels/selective_mark.glsl"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/kernel.h"
#include "vk/shader_reflection.h"
#include "vk/shader_registry.h"

namespace vkp {
namespace {

// Interfaces that disagree with kernel_interface_test.comp in one respect each.
struct ShortPush {  // 20 bytes where the shader's block has 24
    uint32_t count, scale, offset, pad0, pad1;
};
struct WrongPushKernel : gpu::InterfaceTestKernel {
    using Push = ShortPush;
};
struct ExtraBindingKernel : gpu::InterfaceTestKernel {
    static constexpr uint32_t kBindingCount = 3;
};
struct WrongGroupKernel : gpu::InterfaceTestKernel {
    static constexpr uint32_t kGroupSize = 32;
};

template <typename K> std::string creationError() {
    try {
        vk::Kernel<K> kernel(test::gpu());
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "(created without an error)";
}

std::vector<vk::KernelInterface> everyKernel() {
    using namespace gpu;
    return {vk::interfaceOf<PathTraceKernel>(), vk::interfaceOf<GuidedPathTraceKernel>(),
            vk::interfaceOf<GuidedCachedPathTraceKernel>(), vk::interfaceOf<GuidedLearningPathTraceKernel>(),
            vk::interfaceOf<GuideLearnUpdateKernel>(), vk::interfaceOf<PhotonTraceKernel>(),
            vk::interfaceOf<ImportonTraceKernel>(), vk::interfaceOf<ImportanceSplatKernel>(),
            vk::interfaceOf<ImportanceLookupKernel>(), vk::interfaceOf<PhotonDepositKernel>(),
            vk::interfaceOf<DepositRedistributeKernel>(), vk::interfaceOf<GridCountKernel>(),
            vk::interfaceOf<GridScatterKernel>(), vk::interfaceOf<GridSortCellsKernel>(),
            vk::interfaceOf<GridCopyKernel>(), vk::interfaceOf<ScanBlocksKernel>(), vk::interfaceOf<ScanAddKernel>(),
            vk::interfaceOf<CompactMarkKernel>(), vk::interfaceOf<CompactScatterKernel>(),
            vk::interfaceOf<CompactAdvanceKernel>(), vk::interfaceOf<VisiblePointsKernel>(),
            vk::interfaceOf<CausticEstimateKernel>(), vk::interfaceOf<FinalGatherKernel>(), vk::interfaceOf<GatherReuseKernel>(),
            vk::interfaceOf<SppmUpdateKernel>(), vk::interfaceOf<RadiancePhotonsKernel>(),
            vk::interfaceOf<GuideCacheBuildKernel>(), vk::interfaceOf<ShadowVolumeBuildKernel>(),
            vk::interfaceOf<RasterDirectKernel>(), vk::interfaceOf<AovKernel>(),
            vk::interfaceOf<SelectiveMarkKernel>()};
}

class KernelInterfaceTest : public test::GpuTest {};

// Reflection alone, no device: what every shader built into vkphoton declares is what its
// interface in shaders/shared/kernels/ says.
TEST(KernelInterface, EveryKernelAgreesWithItsShader) {
    for (const vk::KernelInterface& k : everyKernel()) {
        SCOPED_TRACE(k.shader);
        EXPECT_TRUE(vk::interfaceMismatches(k, vk::reflectComputeShader(k.shader, vk::shaderCode(k.shader))).empty())
            << "see the exception of checkKernelInterface";
        EXPECT_NO_THROW(vk::checkKernelInterface(k, vk::shaderCode(k.shader)));
    }
}

TEST(KernelInterface, ReflectionReadsTheDeclarations) {
    const vk::ShaderInterface s = vk::reflectComputeShader("final_gather.comp", vk::shaderCode("final_gather.comp"));
    std::vector<uint32_t> expected;
    for (uint32_t i = 0; i < gpu::FinalGatherKernel::kBindingCount; ++i) expected.push_back(i);
    EXPECT_EQ(s.storageBufferBindings, expected);
    EXPECT_EQ(s.pushConstantBytes, sizeof(gpu::FinalGatherParams));
    EXPECT_EQ(s.localSize[0], gpu::kPhotonEstimateGroupSize);
    EXPECT_EQ(s.localSize[1], 1u);
    EXPECT_EQ(s.localSize[2], 1u);
    EXPECT_TRUE(s.unbindable.empty());
}

TEST_F(KernelInterfaceTest, AgreeingKernelRuns) {
    vk::Context& context = test::gpu();
    std::vector<uint32_t> inputs(1000);
    for (uint32_t i = 0; i < inputs.size(); ++i) inputs[i] = i;
    vk::Buffer in = vk::makeStorageBuffer(context, "interface test inputs", inputs);
    vk::Buffer out(context, "interface test outputs", inputs.size() * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::InterfaceTestKernel> kernel(context);
    kernel.bind(gpu::kInterfaceTestInputBinding, in);
    kernel.bind(gpu::kInterfaceTestOutputBinding, out);
    gpu::InterfaceTestParams params{};
    params.count = static_cast<uint32_t>(inputs.size());
    params.scale = 3;
    params.offset = 7;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        kernel.record(cmd, inputs.size(), params);  // 16 groups of 64: the last one partly idle
        vk::computeToHostBarrier(cmd);
    });
    const auto result = out.download<uint32_t>();
    for (uint32_t i = 0; i < inputs.size(); ++i) ASSERT_EQ(result[i], 3 * i + 7) << "item " << i;
}

// Kernels of one interface share the context's compiled pipeline (compiling is the slow part on
// lavapipe) while each keeps its own descriptor sets: two kernels bound to different buffers
// compute their own results, and a second mismatching creation fails again (failures are not kept).
TEST_F(KernelInterfaceTest, KernelsOfOneInterfaceShareOnePipelineAndKeepTheirOwnBindings) {
    vk::Context& context = test::gpu();
    std::vector<uint32_t> inputs(100);
    for (uint32_t i = 0; i < inputs.size(); ++i) inputs[i] = i;
    vk::Buffer in = vk::makeStorageBuffer(context, "interface test inputs", inputs);
    vk::Buffer out1(context, "outputs 1", inputs.size() * sizeof(uint32_t), vk::kStorageUsage);
    vk::Buffer out2(context, "outputs 2", inputs.size() * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::InterfaceTestKernel> first(context);
    const size_t compiled = context.computePipelineCount();
    vk::Kernel<gpu::InterfaceTestKernel> second(context);
    EXPECT_EQ(context.computePipelineCount(), compiled);
    first.bind(gpu::kInterfaceTestInputBinding, in);
    first.bind(gpu::kInterfaceTestOutputBinding, out1);
    second.bind(gpu::kInterfaceTestInputBinding, in);
    second.bind(gpu::kInterfaceTestOutputBinding, out2);
    gpu::InterfaceTestParams params{};
    params.count = static_cast<uint32_t>(inputs.size());
    params.scale = 2;
    gpu::InterfaceTestParams params2 = params;
    params2.offset = 5;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        first.record(cmd, inputs.size(), params);
        second.record(cmd, inputs.size(), params2);
        vk::computeToHostBarrier(cmd);
    });
    const auto result1 = out1.download<uint32_t>();
    const auto result2 = out2.download<uint32_t>();
    for (uint32_t i = 0; i < inputs.size(); ++i) {
        ASSERT_EQ(result1[i], 2 * i) << "item " << i;
        ASSERT_EQ(result2[i], 2 * i + 5) << "item " << i;
    }
    EXPECT_NE(creationError<WrongPushKernel>(), "(created without an error)");
    EXPECT_NE(creationError<WrongPushKernel>(), "(created without an error)");
    EXPECT_EQ(context.computePipelineCount(), compiled);
}

TEST_F(KernelInterfaceTest, PushConstantMismatchFailsAtCreation) {
    EXPECT_EQ(creationError<WrongPushKernel>(),
              "kernel_interface_test.comp: the shader declares push constants of 24 bytes, the host pushes 20");
}

TEST_F(KernelInterfaceTest, BindingMismatchFailsAtCreation) {
    EXPECT_EQ(creationError<ExtraBindingKernel>(),
              "kernel_interface_test.comp: the shader declares storage buffers at bindings 0..1, the host binds 0..2");
}

TEST_F(KernelInterfaceTest, GroupSizeMismatchFailsAtCreation) {
    EXPECT_EQ(creationError<WrongGroupKernel>(),
              "kernel_interface_test.comp: the shader's workgroup is 64x1x1, the host dispatches 1-D groups of 32");
}

TEST(KernelInterface, EveryDifferenceIsNamed) {
    test::registerTestShaders();
    vk::KernelInterface wrong = vk::interfaceOf<gpu::InterfaceTestKernel>();
    wrong.bindingCount = 1;
    wrong.pushBytes = 16;
    wrong.groupSize = 128;
    try {
        vk::checkKernelInterface(wrong, vk::shaderCode(wrong.shader));
        FAIL() << "no error";
    } catch (const RuntimeError& e) {
        EXPECT_STREQ(e.what(),
                     "kernel_interface_test.comp: the shader declares storage buffers at bindings 0..1, the host binds 0; "
                     "the shader declares push constants of 24 bytes, the host pushes 16; "
                     "the shader's workgroup is 64x1x1, the host dispatches 1-D groups of 128");
    }
}

}  // namespace
}  // namespace vkp
