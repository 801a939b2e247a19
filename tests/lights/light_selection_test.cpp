// Light sampling on the host build of the shared GLSL: solid-angle sampling of triangles against the
// subtended-angle pdf (chi-square) and against Lambert's closed-form irradiance of a polygon; the
// light BVH's selection probabilities against the frequencies it draws (chi-square over the light
// index) and their sum.
#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/chi_square.h"
#include "support/gpu_test_support.h"
#include "lights/light_tree.h"
#include "gpu_scene/scene_buffers.h"
#include "lights/light_cells.h"
#include "shared/intersect.glsl"
#include "shared/light_selection.glsl"
#include "shared/spherical_triangle.glsl"
#include "shaders/light_selection_harness.glsl"
#include "shaders/test_kernels.glsl"
#include "support/test_scenes.h"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {
namespace {

using namespace vkp::gpu;

constexpr double kSignificance = 1e-3;

glm::vec2 uniform2(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    float a = u(rng);
    return glm::vec2(a, u(rng));
}

bool hitsTriangle(glm::vec3 p, glm::vec3 w, glm::vec3 v0, glm::vec3 v1, glm::vec3 v2) {
    float t, b1, b2;
    return intersectTriangle(p, w, v0, v1, v2, kInfinity, t, b1, b2);
}

struct TriangleCase {
    glm::vec3 v0, v1, v2, p;
};

// Triangles seen from in front, obliquely, from close by and from afar (0.008 to 2.9 sr).
const TriangleCase kTriangles[] = {
    {{-1.0f, 1.0f, -1.0f}, {1.0f, 1.0f, -1.0f}, {0.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}},
    {{0.6f, 0.2f, 0.0f}, {0.9f, 0.8f, 0.2f}, {0.4f, 0.6f, 0.7f}, {0.0f, 0.0f, 0.0f}},
    {{-0.3f, 0.2f, -0.4f}, {0.5f, 0.2f, -0.2f}, {0.1f, 0.2f, 0.6f}, {0.05f, 0.0f, 0.0f}},
    {{2.0f, 0.5f, 0.0f}, {2.5f, 1.5f, 0.3f}, {1.8f, 1.2f, 1.0f}, {0.0f, 0.0f, 0.0f}},
    {{5.0f, 0.0f, 0.0f}, {5.0f, 0.6f, 0.0f}, {5.0f, 0.0f, 0.7f}, {0.0f, 0.0f, 0.0f}},
};
// The chi-square bins (32 x 64 over the sphere, ~0.006 sr each) resolve triangles of > 0.1 sr;
// the smaller ones are checked against Lambert's formula below.
constexpr float kChiSquareMinSolidAngle = 0.1f;

TEST(LightSelection, SphericalTriangleSamplingMatchesSubtendedAnglePdf) {
    for (const TriangleCase& c : kTriangles) {
        const float omega = triangleSolidAngle(c.v0, c.v1, c.v2, c.p);
        ASSERT_TRUE(useSphericalSampling(omega)) << omega;
        if (omega < kChiSquareMinSolidAngle) continue;
        std::mt19937 rng(11);
        const auto r = test::chiSquareSphere(
            [&](int, glm::vec3& w) {
                bool ok;
                const glm::vec2 b = sampleSphericalTriangle(c.v0, c.v1, c.v2, c.p, uniform2(rng), ok);
                if (!ok) return false;
                w = glm::normalize((1.0f - b.x - b.y) * c.v0 + b.x * c.v1 + b.y * c.v2 - c.p);
                return true;
            },
            [&](const glm::vec3& w) { return hitsTriangle(c.p, w, c.v0, c.v1, c.v2) ? 1.0 / omega : 0.0; }, 200000,
            32, 64, 16);
        EXPECT_GT(r.pValue, kSignificance) << "solid angle " << omega << "\n" << r.details;
    }
}

// The test can fail: area sampling is not uniform in solid angle for a close, oblique triangle.
TEST(LightSelection, ChiSquareRejectsAreaSamplingAsSolidAngle) {
    const TriangleCase& c = kTriangles[2];
    const float omega = triangleSolidAngle(c.v0, c.v1, c.v2, c.p);
    std::mt19937 rng(12);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) {
            const glm::vec2 b = sampleTriangleBarycentrics(uniform2(rng));
            w = glm::normalize((1.0f - b.x - b.y) * c.v0 + b.x * c.v1 + b.y * c.v2 - c.p);
            return true;
        },
        [&](const glm::vec3& w) { return hitsTriangle(c.p, w, c.v0, c.v1, c.v2) ? 1.0 / omega : 0.0; }, 200000, 32, 64,
        16);
    EXPECT_LT(r.pValue, 1e-6) << r.details;
}

// Lambert's formula: the integral of cos(theta) over the solid angle of a polygon seen from p with
// normal n is (1/2) sum over edges of the angle the edge subtends times n . (unit edge normal).
double lambertCosineIntegral(glm::vec3 p, glm::vec3 n, const glm::vec3 (&v)[3]) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 a = glm::normalize(glm::dvec3(v[i] - p));
        const glm::dvec3 b = glm::normalize(glm::dvec3(v[(i + 1) % 3] - p));
        const glm::dvec3 c = glm::cross(a, b);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(glm::normalize(c), glm::dvec3(n));
    }
    return 0.5 * std::abs(sum);
}

// Both strategies estimate the same irradiance integral (unbiased), each within its standard error
// of Lambert's closed form; the solid-angle one with lower variance for close triangles.
TEST(LightSelection, SolidAngleAndAreaSamplingAgreeWithLambert) {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    for (const TriangleCase& c : kTriangles) {
        const glm::vec3 v[3] = {c.v0, c.v1, c.v2};
        const double exact = lambertCosineIntegral(c.p, n, v);
        std::mt19937 rng(13);
        constexpr int kN = 200000;
        double sums[2] = {0, 0}, sumSq[2] = {0, 0};
        for (int i = 0; i < kN; ++i) {
            for (int mode = 0; mode < 2; ++mode) {
                glm::vec2 b;
                if (mode == 0) {
                    bool ok;
                    b = sampleSphericalTriangle(c.v0, c.v1, c.v2, c.p, uniform2(rng), ok);
                    ASSERT_TRUE(ok);
                } else {
                    b = sampleTriangleBarycentrics(uniform2(rng));
                }
                const glm::vec3 q = (1.0f - b.x - b.y) * c.v0 + b.x * c.v1 + b.y * c.v2;
                const glm::vec3 w = glm::normalize(q - c.p);
                double pdf;
                if (mode == 0) {
                    pdf = triangleLightPdf(c.v0, c.v1, c.v2, c.p, q, true);
                } else {  // the area pdf in solid angle, whatever triangleLightPdf would choose
                    const glm::vec3 cr = glm::cross(c.v1 - c.v0, c.v2 - c.v0);
                    const double d2 = glm::dot(q - c.p, q - c.p);
                    pdf = 2.0 * d2 / (glm::length(cr) * std::abs(glm::dot(w, glm::normalize(cr))));
                }
                const double f = std::max(0.0f, glm::dot(w, n)) / pdf;
                sums[mode] += f;
                sumSq[mode] += f * f;
            }
        }
        for (int mode = 0; mode < 2; ++mode) {
            const double mean = sums[mode] / kN;
            const double se = std::sqrt(std::max(0.0, sumSq[mode] / kN - mean * mean) / kN);
            EXPECT_NEAR(mean, exact, 5.0 * se + 2e-4 * exact) << (mode == 0 ? "solid angle" : "area");
        }
    }
}

TEST(LightSelection, TriangleLightPdfFallsBackToAreaForTinyAndHugeSolidAngles) {
    // Tiny: a 1 cm triangle 10 m away.
    const glm::vec3 a(10.0f, 0.0f, 0.0f), b(10.0f, 0.01f, 0.0f), c(10.0f, 0.0f, 0.01f), p(0.0f);
    const float omega = triangleSolidAngle(a, b, c, p);
    EXPECT_LT(omega, kMinSphericalSolidAngle);
    const glm::vec3 q = (a + b + c) / 3.0f;
    const double area = 0.5 * 0.01 * 0.01;
    EXPECT_NEAR(triangleLightPdf(a, b, c, p, q, true), glm::dot(q, q) / (area * q.x / glm::length(q)), 1e-3 * 1e6);
    // Nearly a hemisphere: a huge triangle just above p.
    const glm::vec3 h0(-1e4f, 1e-3f, -1e4f), h1(1e4f, 1e-3f, -1e4f), h2(0.0f, 1e-3f, 1e4f);
    EXPECT_FALSE(useSphericalSampling(triangleSolidAngle(h0, h1, h2, p)));
}

// A scene with many lights of every kind the tree holds, and directional lights outside it.
Scene manyLightScene(int gridLights, bool directional) {
    Scene scene = test::shadowTestScene();
    Material emitter;
    emitter.name = "emitter";
    emitter.emissive = glm::vec3(5.0f, 4.0f, 3.0f);
    scene.materials.push_back(emitter);
    Material twoSided = emitter;
    twoSided.doubleSided = true;
    twoSided.emissive = glm::vec3(1.0f);
    scene.materials.push_back(twoSided);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    for (int i = 0; i < gridLights; ++i) {
        const glm::vec3 c(u(rng), std::abs(u(rng)) + 0.5f, u(rng));
        Triangle t;
        t.p[0] = c;
        t.p[1] = c + glm::vec3(0.3f, 0.0f, 0.1f * float(i % 3));
        t.p[2] = c + glm::vec3(0.0f, -0.1f * float(i % 2), 0.3f);
        for (glm::vec3& n : t.n) n = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
        t.material = i % 5 == 0 ? 2u : 1u;
        scene.triangles.push_back(t);
        scene.bounds.grow(t.p[0]);
        scene.bounds.grow(t.p[1]);
        scene.bounds.grow(t.p[2]);
        if (i % 7 == 0) test::addPointLight(scene, c + glm::vec3(0.0f, 0.2f, 0.0f), glm::vec3(float(i % 4) + 1.0f));
    }
    if (directional) test::addSunAndSpot(scene, glm::vec3(2.0f), glm::vec3(30.0f));
    return scene;
}

// At many shading points: the bvh sampler's pdfs over all lights sum to 1 (or to less where the
// traversal finds no importance in a subtree: that mass is "no light"), and the frequencies of the
// indices it draws match them (chi-square, bins with small expected counts pooled).
TEST(LightSelection, BvhSelectionPdfMatchesDrawnLights) {
    for (const bool directional : {false, true}) {
        const Scene scene = manyLightScene(100, directional);
        const SceneArrays a = buildSceneArrays(scene, {LightSampler::Bvh});
        const uint32_t count = static_cast<uint32_t>(a.lights.size());
        ASSERT_GT(count, 100u);
        EXPECT_GT(a.lightTree.nodes, 100u);
        EXPECT_LT(a.lightTree.depth, kLightTreeMaxDepth);
        const LightSelectionArrays arrays{a.lightCdf, a.lights};
        std::mt19937 rng(21);
        std::uniform_real_distribution<float> pos(-5.0f, 5.0f);
        for (int point = 0; point < 8; ++point) {
            const glm::vec3 p(pos(rng), std::abs(pos(rng)) * 0.5f, pos(rng));
            const glm::vec3 n = glm::normalize(glm::vec3(pos(rng), pos(rng), pos(rng)));
            std::vector<double> pdf(count);
            double total = 0.0;
            for (uint32_t i = 0; i < count; ++i) total += pdf[i] = selectLightPdf(arrays, count, p, n, i);
            EXPECT_LE(total, 1.0 + 1e-4);
            EXPECT_GT(total, 0.5);
            constexpr int kN = 100000;
            std::vector<double> observed(count, 0.0);
            int none = 0;
            std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
            for (int s = 0; s < kN; ++s) {
                const LightChoice c = selectLight(arrays, count, p, n, u(rng));
                if (c.pdf <= 0.0f) { ++none; continue; }
                ASSERT_LT(c.index, count);
                ASSERT_NEAR(c.pdf, pdf[c.index], 1e-5 + 1e-4 * pdf[c.index]) << "light " << c.index;
                observed[c.index] += 1.0;
            }
            // Pearson chi-square with pooling of expected counts below 5 (the "none" bin included).
            std::vector<std::pair<double, double>> bins;  // expected, observed
            for (uint32_t i = 0; i < count; ++i) bins.push_back({pdf[i] * kN, observed[i]});
            bins.push_back({(1.0 - total) * kN, double(none)});
            std::sort(bins.begin(), bins.end());
            double chi2 = 0.0, poolE = 0.0, poolO = 0.0;
            int dof = -1;
            for (const auto& [e, o] : bins) {
                poolE += e;
                poolO += o;
                if (poolE < 5.0) continue;
                chi2 += (poolO - poolE) * (poolO - poolE) / poolE;
                ++dof;
                poolE = poolO = 0.0;
            }
            if (poolE > 0.0) chi2 += (poolO - poolE) * (poolO - poolE) / std::max(poolE, 1e-9);
            const double pValue = test::chiSquarePValue(chi2, std::max(dof, 1));
            EXPECT_GT(pValue, kSignificance) << "point " << point << " chi2 " << chi2 << " dof " << dof;
        }
    }
}

// The bvh sampler prefers what is near: at a point just below one light, that light is chosen far
// more often than power sampling would (1 / lights here).
TEST(LightSelection, BvhPrefersTheNearLight) {
    const Scene scene = manyLightScene(100, false);
    const SceneArrays a = buildSceneArrays(scene, {LightSampler::Bvh});
    const uint32_t count = static_cast<uint32_t>(a.lights.size());
    const LightSelectionArrays arrays{a.lightCdf, a.lights};
    for (uint32_t i = 0; i < count; ++i) {
        if (a.lights[i].type != kLightTriangle) continue;
        const GpuTriangle& t = a.triangles[a.lights[i].triangle];
        const glm::vec3 c = (glm::vec3(t.v0) + glm::vec3(t.v1) + glm::vec3(t.v2)) / 3.0f;
        const glm::vec3 ng = glm::normalize(glm::cross(glm::vec3(t.v1 - t.v0), glm::vec3(t.v2 - t.v0)));
        const glm::vec3 p = c + 0.05f * ng;
        EXPECT_GT(selectLightPdf(arrays, count, p, -ng, i), 10.0f * a.lights[i].selectPdf) << "light " << i;
        EXPECT_EQ(t.v0.w, float(i));
        break;
    }
}

// Keller & Wald's split, made unbiased by a floor: a light whose primary photons never reach a
// cell (a light behind a slit) is still chosen there with probability floor x its BVH pdf, the
// drawn frequencies match selectLightPdf, and cells without photons use the BVH alone.
TEST(LightSelection, PhotonCellsStillSampleALightWhosePhotonsNeverArrive) {
    const Scene scene = manyLightScene(12, false);
    SceneArrays a = buildSceneArrays(scene, {LightSampler::Photon});
    const uint32_t count = static_cast<uint32_t>(a.lights.size());
    // Photons from lights 3 and 5 only, all in the unit cell [0, 1)^3 around p.
    std::vector<GpuPhoton> photons;
    for (int i = 0; i < 50; ++i)
        photons.push_back(makePhoton(glm::vec3(0.1f + 0.01f * i, 0.5f, 0.5f), glm::vec3(1.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                     glm::vec3(0.0f, 1.0f, 0.0f), kPhotonValid | kPhotonPrimary, 3u));
    photons.push_back(makePhoton(glm::vec3(0.9f, 0.2f, 0.2f), glm::vec3(0.5f), glm::vec3(0.0f, 1.0f, 0.0f),
                                 glm::vec3(0.0f, 1.0f, 0.0f), kPhotonValid | kPhotonPrimary, 5u));
    constexpr float kFloor = 0.25f;
    const LightCellStats stats = buildLightCells(a.lightCdf, count, photons, 1.0f, 8, kFloor);
    EXPECT_EQ(stats.cells, 1u);
    EXPECT_EQ(stats.photons, 51u);
    EXPECT_DOUBLE_EQ(stats.meanCandidates, 2.0);
    const LightSelectionArrays arrays{a.lightCdf, a.lights};
    const glm::vec3 p(0.5f, 0.5f, 0.5f), n(0.0f, 1.0f, 0.0f);
    uint32_t hidden = 0;  // a light that can reach p but sent no photon there
    while (hidden == 3u || hidden == 5u || selectLightBvhPdf(arrays, count, p, n, hidden) <= 0.0f) ++hidden;
    ASSERT_LT(hidden, count);
    const float bvh0 = selectLightBvhPdf(arrays, count, p, n, hidden);
    EXPECT_NEAR(selectLightPdf(arrays, count, p, n, hidden), kFloor * bvh0, 1e-7f);
    const float bvh3 = selectLightBvhPdf(arrays, count, p, n, 3u);
    EXPECT_NEAR(selectLightPdf(arrays, count, p, n, 3u), kFloor * bvh3 + (1.0f - kFloor) * 50.0f / 50.5f, 1e-3f);
    double total = 0.0;
    std::vector<double> pdf(count);
    for (uint32_t i = 0; i < count; ++i) total += pdf[i] = selectLightPdf(arrays, count, p, n, i);
    EXPECT_NEAR(total, kFloor * 1.0 + (1.0 - kFloor), 1e-4);
    // The drawn frequencies (chi-square over the light index).
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    constexpr int kN = 200000;
    std::vector<double> observed(count, 0.0);
    for (int s = 0; s < kN; ++s) {
        const LightChoice c = selectLight(arrays, count, p, n, u(rng));
        ASSERT_GT(c.pdf, 0.0f);
        ASSERT_NEAR(c.pdf, pdf[c.index], 1e-5 + 1e-4 * pdf[c.index]);
        observed[c.index] += 1.0;
    }
    double chi2 = 0.0;
    int dof = -1;
    for (uint32_t i = 0; i < count; ++i) {
        const double e = pdf[i] * kN;
        if (e < 5.0) continue;
        chi2 += (observed[i] - e) * (observed[i] - e) / e;
        ++dof;
    }
    EXPECT_GT(test::chiSquarePValue(chi2, dof), kSignificance) << chi2 << " dof " << dof;
    EXPECT_GT(observed[hidden], 0.5 * kFloor * bvh0 * kN);  // the light behind the slit is drawn
    // A point in a cell without photons: the BVH's distribution.
    const glm::vec3 q(3.5f, 0.5f, 0.5f);
    for (uint32_t i = 0; i < count; ++i)
        EXPECT_EQ(selectLightPdf(arrays, count, q, n, i), selectLightBvhPdf(arrays, count, q, n, i));
}

TEST(LightSelection, PowerModeIsTheCdf) {
    const Scene scene = manyLightScene(20, true);
    const SceneArrays a = buildSceneArrays(scene, {LightSampler::Power});
    const uint32_t count = static_cast<uint32_t>(a.lights.size());
    const LightSelectionArrays arrays{a.lightCdf, a.lights};
    double total = 0.0;
    for (uint32_t i = 0; i < count; ++i) {
        EXPECT_EQ(selectLightPdf(arrays, count, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), i), a.lights[i].selectPdf);
        total += a.lights[i].selectPdf;
    }
    EXPECT_NEAR(total, 1.0, 1e-5);
    const LightChoice c = selectLight(arrays, count, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 0.5f);
    EXPECT_EQ(c.pdf, a.lights[c.index].selectPdf);
    EXPECT_EQ(parseLightSampler("bvh"), LightSampler::Bvh);
    EXPECT_THROW(parseLightSampler("nope"), InputError);
}


// The light sampler's shared functions on the GPU against their C++ build (the shader harness of
// tests/shared/shared_functions_test.cpp, for light_selection.glsl and spherical_triangle.glsl): power,
// bvh and photon-cell selection over a hundred lights of every kind, and solid-angle triangle
// samples. The light BVH's descent compares float importances, so where u falls within rounding
// of a child's probability GPU and CPU may take different children: a few differing choices are
// allowed, their pdfs must then still agree with selectLightPdf on each side.
class LightSelectionGpu : public test::GpuTest {};

std::vector<LightHarnessInput> lightHarnessInputs(uint32_t seed, uint32_t count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, kOneMinusEpsilon);
    std::uniform_real_distribution<float> sym(-1.0f, 1.0f);
    std::vector<LightHarnessInput> inputs(count);
    for (LightHarnessInput& in : inputs) {
        const glm::vec3 p(4.0f * sym(rng), 1.5f + 1.5f * sym(rng), 4.0f * sym(rng));
        const glm::vec3 n = glm::normalize(glm::vec3(sym(rng), sym(rng), sym(rng)) + glm::vec3(0.0f, 1e-3f, 0.0f));
        const glm::vec3 toward = glm::normalize(glm::vec3(sym(rng), sym(rng), sym(rng)) + glm::vec3(1e-3f, 0.0f, 0.0f));
        const glm::vec3 centre = p + (0.5f + 2.5f * unit(rng)) * toward;
        in.p = glm::vec4(p, 0.0f);
        in.n = glm::vec4(n, 0.0f);
        in.v0 = glm::vec4(centre + 0.8f * glm::vec3(sym(rng), sym(rng), sym(rng)), 0.0f);
        in.v1 = glm::vec4(centre + 0.8f * glm::vec3(sym(rng), sym(rng), sym(rng)), 0.0f);
        in.v2 = glm::vec4(centre + 0.8f * glm::vec3(sym(rng), sym(rng), sym(rng)), 0.0f);
        in.u = glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng));
    }
    return inputs;
}

std::vector<LightHarnessOutput> runLightHarness(const SceneArrays& a, const std::vector<LightHarnessInput>& inputs) {
    vk::Context& context = test::gpu();
    vk::Buffer in = vk::makeStorageBuffer(context, "light harness inputs", inputs);
    vk::Buffer out(context, "light harness outputs", inputs.size() * sizeof(LightHarnessOutput), vk::kStorageUsage);
    vk::Buffer selection = vk::makeStorageBuffer(context, "light selection", a.lightCdf);
    vk::Buffer lights = vk::makeStorageBuffer(context, "lights", a.lights);
    vk::Kernel<LightTestKernel> kernel(context);
    kernel.bind(kLightTestInputBinding, in);
    kernel.bind(kLightTestOutputBinding, out);
    kernel.bind(kLightTestSelectionBinding, selection);
    kernel.bind(kLightTestLightBinding, lights);
    const LightTestParams push{static_cast<uint32_t>(inputs.size()), static_cast<uint32_t>(a.lights.size())};
    context.submitAndWait([&](VkCommandBuffer cmd) {
        kernel.record(cmd, inputs.size(), push);
        vk::computeToHostBarrier(cmd);
    });
    return out.download<LightHarnessOutput>();
}

bool closeTo(float a, float b, float absolute, float relative) {
    return std::isfinite(a) == std::isfinite(b) && (!std::isfinite(a) || std::abs(a - b) <= absolute + relative * std::abs(a));
}

SceneArrays harnessLights(LightSampler sampler) {
    SceneArrays a = buildSceneArrays(manyLightScene(100, true), {sampler});
    if (sampler == LightSampler::Photon) {  // cells of 1 m holding photons of random lights
        std::mt19937 rng(41);
        std::uniform_real_distribution<float> sym(-1.0f, 1.0f);
        std::vector<GpuPhoton> photons;
        for (int i = 0; i < 4000; ++i)
            photons.push_back(makePhoton(glm::vec3(4.0f * sym(rng), 1.5f + 1.5f * sym(rng), 4.0f * sym(rng)),
                                         glm::vec3(0.5f + 0.5f * sym(rng)), glm::vec3(0.0f, 1.0f, 0.0f),
                                         glm::vec3(0.0f, 1.0f, 0.0f), kPhotonValid | kPhotonPrimary,
                                         static_cast<uint32_t>(rng() % a.lights.size())));
        const LightCellStats stats = buildLightCells(a.lightCdf, static_cast<uint32_t>(a.lights.size()), photons, 1.0f, 8, 0.25f);
        EXPECT_GT(stats.cells, 50u);
    }
    return a;
}

TEST_F(LightSelectionGpu, SelectionAndTriangleSamplingMatchTheHostBuild) {
    for (const LightSampler sampler : {LightSampler::Power, LightSampler::Bvh, LightSampler::Photon}) {
        SCOPED_TRACE(lightSamplerName(sampler));
        const SceneArrays a = harnessLights(sampler);
        const uint32_t count = static_cast<uint32_t>(a.lights.size());
        const LightSelectionArrays arrays{a.lightCdf, a.lights};
        const auto inputs = lightHarnessInputs(7 + static_cast<uint32_t>(sampler), 4096);
        const auto gpuOut = runLightHarness(a, inputs);
        ASSERT_EQ(gpuOut.size(), inputs.size());
        int differentChoices = 0, triangleFailures = 0, failures = 0, sampled = 0;
        for (size_t i = 0; i < inputs.size() && failures < 5; ++i) {
            const LightHarnessOutput cpu = evaluateLightHarness(arrays, count, inputs[i]);
            const LightHarnessOutput& gpu = gpuOut[i];
            const uint32_t cpuIndex = glm::floatBitsToUint(cpu.selection.x), gpuIndex = glm::floatBitsToUint(gpu.selection.x);
            ASSERT_LT(gpuIndex, count);
            // Each side's pdf of its own choice is its selectLightPdf (MIS depends on it).
            EXPECT_TRUE(closeTo(gpu.selection.y, gpu.selection.z, 1e-6f, 1e-4f)) << "input " << i;
            if (gpuIndex != cpuIndex) {
                ++differentChoices;
                EXPECT_TRUE(closeTo(selectLightPdf(arrays, count, glm::vec3(inputs[i].p), glm::vec3(inputs[i].n), gpuIndex),
                                    gpu.selection.y, 1e-6f, 1e-3f)) << "input " << i;
            } else if (!closeTo(cpu.selection.y, gpu.selection.y, 1e-6f, 1e-3f)) {
                ++failures;
                ADD_FAILURE() << "input " << i << " light " << cpuIndex << ": pdf CPU " << cpu.selection.y << " GPU " << gpu.selection.y;
            }
            if (!closeTo(cpu.selection.w, gpu.selection.w, 1e-6f, 1e-3f)) {
                ++failures;
                ADD_FAILURE() << "input " << i << ": selectLightPdf(other) CPU " << cpu.selection.w << " GPU " << gpu.selection.w;
            }
            if (cpu.triangle.z != gpu.triangle.z) {
                if (triangleFailures < 5) fmt::print("triangle input {}: ok CPU {} GPU {}\n", i, cpu.triangle.z, gpu.triangle.z);
                ++triangleFailures;
                continue;
            }
            if (cpu.triangle.z == 0.0f) continue;
            if (!closeTo(cpu.triangle.w, gpu.triangle.w, 1e-4f, 2e-3f)) {
                ++failures;
                ADD_FAILURE() << "input " << i << ": triangleLightPdf CPU " << cpu.triangle.w << " GPU " << gpu.triangle.w;
            }
            // The warp is compared where the renderer uses it (useSphericalSampling).
            if (!useSphericalSampling(1.0f / cpu.triangle.w)) continue;
            ++sampled;
            if (!closeTo(cpu.triangle.x, gpu.triangle.x, 2e-3f, 0.0f) || !closeTo(cpu.triangle.y, gpu.triangle.y, 2e-3f, 0.0f)) {
                if (triangleFailures < 5)
                    fmt::print("triangle input {}: CPU ({}, {}) GPU ({}, {}), solid angle {}\n", i, cpu.triangle.x,
                               cpu.triangle.y, gpu.triangle.x, gpu.triangle.y, 1.0f / cpu.triangle.w);
                ++triangleFailures;
            }
        }
        EXPECT_EQ(failures, 0);
        EXPECT_LE(differentChoices, static_cast<int>(inputs.size()) / 100) << "choices differing from the C++ build";
        // Measured: 0.2-0.3 % on lavapipe (the warp's float cancellation for triangles of a few
        // 1e-3 sr), 1.02 % on an NVIDIA H100 (driver 580: division and square root within
        // Vulkan's 2.5-3 ulp, not correctly rounded); with the former asin-based angles 30 %.
        EXPECT_LE(triangleFailures, sampled / 50) << "spherical triangle samples differing, of " << sampled;
        EXPECT_GT(sampled, static_cast<int>(inputs.size()) * 3 / 4);
    }
}

// The comparison can fail: the GPU's bvh choices against the C++ build reading power selection.
TEST_F(LightSelectionGpu, HarnessDetectsAMismatch) {
    const SceneArrays bvh = harnessLights(LightSampler::Bvh);
    const SceneArrays power = harnessLights(LightSampler::Power);
    const uint32_t count = static_cast<uint32_t>(power.lights.size());
    const auto inputs = lightHarnessInputs(3, 1024);
    const auto gpuOut = runLightHarness(bvh, inputs);
    int differing = 0;
    for (size_t i = 0; i < inputs.size(); ++i)
        differing += evaluateLightHarness(LightSelectionArrays{power.lightCdf, power.lights}, count, inputs[i]).selection.y !=
                     gpuOut[i].selection.y;
    EXPECT_GT(differing, static_cast<int>(inputs.size()) / 2);
}

}  // namespace
}  // namespace vkp
