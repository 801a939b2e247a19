// Silent terminations (shaders/shared/kernels/terminations.glsl, host/render/terminations.h):
// a BVH deeper than the traversal stack, and a scene whose rays need more loop iterations than
// lavapipe's budget, are counted and reported; an ordinary scene reports zero of every kind.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bvh/bvh.h"
#include "support/gpu_test_support.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
#include "render/renderer.h"
#include "render/terminations.h"
#include "shaders/test_kernels.glsl"
#include "shared/bvh_traverse.glsl"
#include "support/test_scenes.h"
#include "vk/buffer.h"
#include "vk/buffer_view.h"
#include "vk/kernel.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

// A "comb" `levels` inner nodes deep, deeper than the stack (gpu::kBvhMaxDepth), which the host
// build never makes: along a ray from (-1, 0, 0) towards +x, each inner node's children are the
// next inner node (box entered at t = 1, visited first) and a leaf entered at t = 6 (pushed), whose
// triangle 0 lies off the ray. The deepest node is a leaf with triangle 1, hit at t = 8.
struct Comb {
    std::vector<gpu::GpuBvhNode> nodes;
    std::vector<gpu::GpuTriangle> triangles;
};

gpu::GpuBvhNode node(glm::vec3 lo, glm::vec3 hi, uint32_t leftOrFirst, uint32_t count) {
    gpu::GpuBvhNode n;
    n.boundsMin = lo;
    n.boundsMax = hi;
    n.leftOrFirst = leftOrFirst;
    n.count = count;
    return n;
}

Comb comb(uint32_t levels) {
    Comb c;
    gpu::GpuTriangle off;
    off.v0 = glm::vec4(100, 100, 100, 0);
    off.v1 = glm::vec4(101, 100, 100, 0);
    off.v2 = glm::vec4(100, 101, 100, 0);
    gpu::GpuTriangle wall;  // the plane x = 7 around the x axis
    wall.v0 = glm::vec4(7, -1, -1, 0);
    wall.v1 = glm::vec4(7, 3, -1, 0);
    wall.v2 = glm::vec4(7, -1, 3, 0);
    c.triangles = {off, wall};
    const glm::vec3 innerLo(0, -1, -1), innerHi(10, 3, 3), leafLo(5, -1, -1);
    c.nodes.push_back(node(innerLo, innerHi, 1, 0));
    for (uint32_t level = 0; level < levels; ++level) {
        const uint32_t next = static_cast<uint32_t>(c.nodes.size());
        const bool last = level + 1 == levels;
        // Children at next (inner, or the final leaf with the wall) and next + 1 (a leaf off the ray).
        c.nodes.push_back(last ? node(innerLo, innerHi, 1, 1) : node(innerLo, innerHi, next + 2, 0));
        c.nodes.push_back(node(leafLo, innerHi, 0, 1));
    }
    return c;
}

TEST(Terminations, TheHostTraversalOfATreeDeeperThanItsStackNotesAnOverflow) {
    for (uint32_t levels : {8u, gpu::kBvhMaxDepth + 12}) {
        const Comb c = comb(levels);
        const gpu::BvhArrays arrays{c.nodes, c.triangles};
        gpu::gTerminations = 0;
        float t, b1, b2;
        uint32_t tri;
        ASSERT_TRUE(gpu::traceClosest(arrays, glm::vec3(-1, 0, 0), glm::vec3(1, 0, 0), 1e30f, false, t, tri, b1, b2));
        EXPECT_FLOAT_EQ(t, 8.0f);  // the skipped leaves hold nothing on the ray
        EXPECT_EQ(tri, 1u);
        const bool overflow = (gpu::gTerminations & (1u << gpu::kTerminationStackOverflow)) != 0;
        EXPECT_EQ(overflow, levels > gpu::kBvhMaxDepth) << levels << " levels";
        EXPECT_EQ(gpu::gTerminations & ~(1u << gpu::kTerminationStackOverflow), 0u);
    }
    gpu::gTerminations = 0;
}

struct TestRay {
    glm::vec4 origin;  // w = tMax
    glm::vec4 direction;
};

class TerminationsGpu : public test::GpuTest {};

// tests/shaders/bvh_trace_test.comp counts each ray whose traversal was cut as a sample.
uint32_t gpuStackOverflows(const Comb& c, uint32_t rayCount) {
    vk::Context& context = test::gpu();
    const std::vector<TestRay> rays(rayCount, TestRay{glm::vec4(-1, 0, 0, 1e30f), glm::vec4(1, 0, 0, 0)});
    vk::Buffer rayBuffer = vk::makeStorageBuffer(context, "rays", rays);
    vk::Buffer nodeBuffer = vk::makeTexelReadBuffer(context, "nodes", c.nodes);
    vk::Buffer triBuffer = vk::makeTexelReadBuffer(context, "triangles", c.triangles);
    const vk::BvhTexelViews texels(context, nodeBuffer, c.nodes.size(), triBuffer, c.triangles.size());
    vk::Buffer hitBuffer(context, "hits", rays.size() * 20, vk::kStorageUsage);
    vk::Kernel<gpu::BvhTestKernel> kernel(context);
    kernel.bind(gpu::kBvhTestRayBinding, rayBuffer);
    kernel.bind(gpu::kBvhTestNodeBinding, nodeBuffer);
    kernel.bind(gpu::kBvhTestTriangleBinding, triBuffer);
    kernel.bind(gpu::kBvhTestHitBinding, hitBuffer);
    const std::vector<gpu::GpuInstanceHeader> noInstances(1);  // one tree, no top level
    vk::Buffer instanceBuffer = vk::makeStorageBuffer(context, "instances", noInstances);
    kernel.bind(gpu::kBvhTestInstanceBinding, instanceBuffer);
    kernel.bind(vk::KernelBindings{{}, nullptr, std::nullopt, &texels.views()});
    clearTerminations(context);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        kernel.record(cmd, rayCount, rayCount);
        vk::computeToHostBarrier(cmd);
    });
    const TerminationCounts counts = readTerminations(context);
    EXPECT_EQ(counts.total(), counts.at(gpu::kTerminationStackOverflow, gpu::kTerminationSamples));
    return counts.at(gpu::kTerminationStackOverflow, gpu::kTerminationSamples);
}

TEST_F(TerminationsGpu, EveryRayThatOverflowsTheTraversalStackIsCounted) {
    EXPECT_EQ(gpuStackOverflows(comb(gpu::kBvhMaxDepth + 12), 100), 100u);
    EXPECT_EQ(gpuStackOverflows(comb(8), 100), 0u);
}

// A floor under `slivers` thin triangles whose boxes all cover the middle of the view while the
// triangles themselves are lines: every ray through the middle visits every leaf, far more
// iterations than lavapipe's budget of 65535.
Scene sliverScene(uint32_t slivers) {
    Scene scene = test::shadowTestScene();
    test::addQuad(scene, {-3, -3, -2}, {3, -3, -2}, {3, 3, -2}, {-3, 3, -2});
    for (uint32_t i = 0; i < slivers; ++i) {
        const float angle = 0.785f + 0.2f * std::sin(float(i) * 2.39996f);
        const float z = -1.0f + 2.0f * std::fmod(float(i) * 0.618034f, 1.0f);
        const glm::vec3 a(std::cos(angle), std::sin(angle), 0.0f);
        const glm::vec3 side(-a.y * 1e-3f, a.x * 1e-3f, 0.0f);
        Triangle t;
        t.p[0] = -a + glm::vec3(0, 0, z);
        t.p[1] = a + glm::vec3(0, 0, z);
        t.p[2] = a + side + glm::vec3(0, 0, z);
        for (int v = 0; v < 3; ++v) {
            t.n[v] = glm::vec3(0, 0, 1);
            t.uv[v] = glm::vec2(0.0f);
            scene.bounds.grow(t.p[v]);
        }
        scene.triangles.push_back(t);
    }
    PunctualLight spot;  // down through the slivers, so photon paths are cut too
    spot.type = LightType::Spot;
    spot.position = glm::vec3(0.1f, 0.05f, 4.0f);
    spot.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    spot.intensity = glm::vec3(50.0f);
    spot.innerConeAngle = 0.05f;
    spot.outerConeAngle = 0.1f;
    scene.lights.push_back(spot);
    scene.cameras.push_back(test::lookAt({0, 0, 5}, {0, 0, 0}, 0.3f));
    return scene;
}

FrameSettings tiny() {
    FrameSettings s = test::smallFrame(8, 2);
    s.maxDepth = 3;
    return s;
}

uint64_t sumOf(const Stats& stats, uint32_t kind) {
    uint64_t sum = 0;
    for (uint32_t subject = 0; subject < gpu::kTerminationSubjectCount; ++subject)
        sum += stats.get<uint64_t>("terminations." + terminationKindName(kind) + "." + terminationSubjectName(subject));
    return sum;
}

bool warnsOfCuts(const Stats& stats) {
    for (const std::string& w : stats.warnings())
        if (w.find("cut short") != std::string::npos) return true;
    return false;
}

// On lavapipe the sliver scene's rays run past the loop budget and are counted; a driver without
// the budget (NVIDIA) runs them to the end, and then nothing may be counted or warned about.
TEST_F(TerminationsGpu, RaysPastLavapipesLoopBudgetAreCountedAndWarnedAbout) {
    const Scene scene = sliverScene(100000);
    Renderer renderer(test::gpu(), scene);
    const bool budget = test::onLavapipe();
    const RenderResult path = renderer.render<PathIntegrator>(tiny());
    if (budget) EXPECT_GT(path.stats.get<uint64_t>("terminations.loopLimit.samples"), 0u);
    else EXPECT_EQ(sumOf(path.stats, gpu::kTerminationLoopLimit), 0u);
    EXPECT_LE(path.stats.get<uint64_t>("terminations.loopLimit.samples"), 8u * 8u * 2u);
    EXPECT_EQ(warnsOfCuts(path.stats), budget);

    PhotonIntegratorSettings p;
    p.globalPaths = 500;
    p.causticPaths = 0;
    p.deposit.mode = DepositMode::All;  // no importons: each would be cut too, slowly
    p.gatherRays = 1;
    FrameSettings s = tiny();
    s.samplesPerPixel = 1;
    const RenderResult photon = renderer.render<PhotonIntegrator>(s, p);
    if (budget) {
        EXPECT_GT(photon.stats.get<uint64_t>("terminations.loopLimit.photonPaths"), 0u);
        EXPECT_GT(photon.stats.get<uint64_t>("terminations.loopLimit.samples"), 0u);
    } else {
        EXPECT_EQ(sumOf(photon.stats, gpu::kTerminationLoopLimit), 0u);
    }
    EXPECT_EQ(warnsOfCuts(photon.stats), budget);
}

TEST_F(TerminationsGpu, AnOrdinarySceneReportsNoneOfAnyKind) {
    const Scene scene = test::shippedScene("cornell-box");
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = tiny();
    s.width = s.height = 16;
    const RenderResult path = renderer.render<PathIntegrator>(s);
    PhotonIntegratorSettings p;
    p.globalPaths = 5000;
    p.causticPaths = 1000;
    const RenderResult photon = renderer.render<PhotonIntegrator>(s, p);
    for (const RenderResult* r : {&path, &photon}) {
        for (uint32_t kind = 0; kind < gpu::kTerminationKindCount; ++kind) EXPECT_EQ(sumOf(r->stats, kind), 0u);
        EXPECT_FALSE(warnsOfCuts(r->stats));
        EXPECT_TRUE(r->stats.toJson()["terminations"]["stackOverflow"].contains("photonPaths"));
    }
}

}  // namespace
}  // namespace vkp
