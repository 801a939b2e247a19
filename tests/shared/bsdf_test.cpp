// The glTF BSDF (shared/bsdf.glsl, host build; shared_functions_test shows the GPU build computes
// the same): closed-form values, white furnaces per direction, reciprocity, and chi-square tests of
// sampling against the pdf over a grid of material parameters.
#include <cmath>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "support/chi_square.h"
#include "gpu_scene/scene_buffers.h"
#include "support/gpu_test_support.h"
#include "shared/bsdf.glsl"
#include "shaders/test_kernels.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {
namespace {

using namespace vkp::gpu;

glm::vec3 direction(float cosTheta, float phi) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return glm::vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

// Directional albedo by sampling: the mean of the sample weights (red channel).
double sampledAlbedo(const BsdfParams& p, float cosWo, int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    const glm::vec3 wo = direction(cosWo, 0.0f);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
        if (s.lobe != kLobeNone) sum += s.weight.x;
    }
    return sum / n;
}

// Directional albedo by quadrature of evalBsdf (midpoint rule in cos theta and phi; the
// non-delta part only), independent of the sampling code.
double integratedAlbedo(const BsdfParams& p, float cosWo, int steps = 1024) {
    const glm::vec3 wo = direction(cosWo, 0.0f);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        // cos theta = t^2 concentrates nodes near the horizon, where grazing lobes live.
        const double t = (i + 0.5) / steps;
        const double mu = t * t;
        for (int j = 0; j < steps / 2; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / (steps / 2);
            const glm::vec3 wi = direction(static_cast<float>(mu), static_cast<float>(phi));
            sum += evalBsdf(p, wo, wi).x * mu * 2.0 * t;  // d(mu) = 2 t dt
        }
    }
    return sum * (1.0 / steps) * (2.0 * kPi / (steps / 2));
}

// KHR_materials_specular's specularFactor 0 is Lambert: f = baseColor / pi exactly, cosine
// sampling, and every sample of a white surface carries weight 1 (a white furnace of exactly 1).
TEST(Bsdf, SpecularZeroIsExactlyLambert) {
    BsdfParams p = makeBsdfParams(glm::vec3(0.5f, 0.25f, 1.0f), 0.0f, 0.3f);
    p.specular = 0.0f;
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 wo = direction(std::max(u(rng), 1e-3f), 6.28f * u(rng));
        const glm::vec3 wi = direction(std::max(u(rng), 1e-3f), 6.28f * u(rng));
        const glm::vec3 f = evalBsdf(p, wo, wi);
        EXPECT_FLOAT_EQ(f.x, 0.5f * kInvPi);
        EXPECT_FLOAT_EQ(f.z, 1.0f * kInvPi);
        EXPECT_FLOAT_EQ(pdfBsdf(p, wo, wi), wi.z * kInvPi);
    }
    p.baseColor = glm::vec3(1.0f);
    for (float cosWo : {0.05f, 0.5f, 1.0f}) {
        const glm::vec3 wo = direction(cosWo, 1.0f);
        for (int i = 0; i < 2000; ++i) {
            const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
            ASSERT_EQ(s.lobe, kLobeDiffuse);
            EXPECT_NEAR(s.weight.x, 1.0f, 1e-5f);
        }
    }
}

// glTF Appendix B for a rough (roughness 1, alpha 1) white metal at normal incidence has the
// closed form 1 - ln 2: D = 1/pi, G2 = 2 cos_i / (1 + cos_i), F = 1, so
// albedo = int_0^1 mu / (1 + mu) dmu.
TEST(Bsdf, RoughWhiteMetalFurnaceIsOneMinusLnTwo) {
    BsdfParams p = makeBsdfParams(glm::vec3(1.0f), 1.0f, 1.0f);
    p.flags = kBsdfNoEnergyCompensation;
    const double expected = 1.0 - std::log(2.0);  // 0.3069
    EXPECT_NEAR(integratedAlbedo(p, 1.0f), expected, 2e-3);
    EXPECT_NEAR(sampledAlbedo(p, 1.0f, 400000, 2), expected, 3e-3);
}

// White furnace per direction of the spec's plain BRDF: sampling (weights) against quadrature of
// evaluation, and the values themselves (the spec's fresnel_mix is not energy conserving at
// grazing angles: smooth dielectrics return more than they receive there).
struct FurnaceCase {
    bool compensated;
    float metallic;
    float roughness;
    float cosWo;
    double expected;   // quadrature of Appendix B (this file's integratedAlbedo), 3 digits
    double tolerance;
};

TEST(Bsdf, WhiteFurnacePerDirection) {
    const FurnaceCase cases[] = {
        // the spec's plain BRDF (render --no-energy-compensation):
        // rough white dielectric (ior 1.5): a little below 1 (the GGX layer loses energy to G2)
        {false, 0.0f, 1.0f, 1.0f, 0.972, 0.004},
        {false, 0.0f, 1.0f, 0.5f, 0.977, 0.004},
        // glossy white dielectric: 1 at normal incidence, above 1 towards grazing
        {false, 0.0f, 0.3f, 1.0f, 0.999, 0.004},
        {false, 0.0f, 0.3f, 0.1f, 1.283, 0.02},
        // white metals: single-scattering GGX loses energy with roughness
        {false, 1.0f, 0.3f, 1.0f, 0.991, 0.004},
        {false, 1.0f, 0.6f, 1.0f, 0.823, 0.004},
        {false, 1.0f, 1.0f, 0.5f, 0.450, 0.004},
        // with Kulla-Conty compensation (the default): a white metal returns all the light, whatever
        // its roughness (1 up to the tables' bilinear interpolation: 1 %); a white dielectric gains
        // the multiple scattering of its Fresnel-weighted layer only (0.972 -> 0.974, Favg ~ 0.09)
        {true, 1.0f, 1.0f, 1.0f, 1.000, 0.01},
        {true, 1.0f, 1.0f, 0.5f, 1.000, 0.01},
        {true, 1.0f, 0.6f, 1.0f, 1.000, 0.01},
        {true, 1.0f, 0.3f, 1.0f, 1.000, 0.01},
        {true, 0.0f, 1.0f, 1.0f, 0.974, 0.004},
    };
    uint32_t seed = 10;
    for (const FurnaceCase& c : cases) {
        BsdfParams p = makeBsdfParams(glm::vec3(1.0f), c.metallic, c.roughness);
        if (!c.compensated) p.flags = kBsdfNoEnergyCompensation;
        const double integrated = integratedAlbedo(p, c.cosWo);
        const double sampled = sampledAlbedo(p, c.cosWo, 200000, seed++);
        EXPECT_NEAR(integrated, c.expected, c.tolerance) << (c.compensated ? "compensated" : "plain") << " metallic " << c.metallic << " roughness " << c.roughness
                                                         << " cos " << c.cosWo;
        EXPECT_NEAR(sampled, integrated, 0.01 * integrated + 0.002)
            << "metallic " << c.metallic << " roughness " << c.roughness << " cos " << c.cosWo;
    }
}

// KHR_materials_ior ior = 0: the specular-glossiness compatibility mode, an infinite ior whose
// Fresnel term is 1 in every direction (scaled by KHR_materials_specular); transmission reflects all.
TEST(Bsdf, IorZeroIsAnInfiniteIorWithFresnelOne) {
    BsdfParams p = makeBsdfParams(glm::vec3(0.5f), 0.0f, 0.5f);
    p.ior = 0.0f;
    p.specular = 0.8f;
    p.specularColor = glm::vec3(1.0f, 0.5f, 2.0f);
    for (float c : {1.0f, 0.5f, 0.05f}) {
        const glm::vec3 f = dielectricFresnel(p, c);
        EXPECT_FLOAT_EQ(f.x, 0.8f);
        EXPECT_FLOAT_EQ(f.y, 0.4f);
        EXPECT_FLOAT_EQ(f.z, 0.8f);
    }
    p.transmission = 1.0f;
    for (float u : {0.0f, 0.5f, 0.99f}) {
        const BsdfSample s = sampleDielectric(p, glm::normalize(glm::vec3(0.3f, 0.0f, 0.9f)), true, true, glm::vec2(u, 0.5f));
        EXPECT_EQ(s.lobe, kLobeDelta) << "ior 0 must not refract";
    }
}

// Evaluation is reciprocal: f(wo, wi) = f(wi, wo), for every material of the grid.
TEST(Bsdf, EvaluationIsReciprocal) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (float roughness : {0.05f, 0.3f, 1.0f})
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float specular : {0.0f, 0.5f, 1.0f}) {
                BsdfParams p = makeBsdfParams(glm::vec3(0.9f, 0.5f, 0.2f), metallic, roughness);
                p.specular = specular;
                p.specularColor = glm::vec3(1.0f, 2.0f, 0.5f);
                // Layers: clear coat and sheen on some, compensation off on others.
                if (specular == 0.5f) {
                    p.clearcoat = 0.8f;
                    p.clearcoatRoughness = roughness;
                }
                if (metallic == 0.5f) {
                    p.sheenColor = glm::vec3(0.9f, 0.4f, 0.6f);
                    p.sheenRoughness = 0.6f;
                }
                if (roughness == 0.3f) p.flags = kBsdfNoEnergyCompensation;
                for (int i = 0; i < 200; ++i) {
                    const glm::vec3 a = direction(std::max(u(rng), 0.01f), 6.28f * u(rng));
                    const glm::vec3 b = direction(std::max(u(rng), 0.01f), 6.28f * u(rng));
                    const glm::vec3 fab = evalBsdf(p, a, b);
                    const glm::vec3 fba = evalBsdf(p, b, a);
                    for (int k = 0; k < 3; ++k) ASSERT_NEAR(fab[k], fba[k], 1e-4f * fab[k] + 1e-6f);
                }
            }
}

// Sampling against pdf over a grid of (roughness, metallic, specular, specular colour, clear coat
// with and without its own normal, sheen) at two angles; every sample's pdf and weight must agree
// with pdfBsdf and evalBsdf.
struct GridCase {
    float roughness;
    float metallic;
    float specular;
    glm::vec3 specularColor;
    float cosWo;
    float clearcoat;
    float sheen;
    bool coatNormal;  // the coat's normal tilted 26 degrees off the shading normal (kBsdfCoatNormal)
};

std::string describe(const GridCase& c) {
    std::ostringstream s;
    s << "roughness " << c.roughness << " metallic " << c.metallic << " specular " << c.specular << " colour ("
      << c.specularColor.x << "," << c.specularColor.y << "," << c.specularColor.z << ") cos " << c.cosWo
      << " clearcoat " << c.clearcoat << " sheen " << c.sheen << (c.coatNormal ? " tilted coat normal" : "");
    return s.str();
}

std::vector<GridCase> gridCases() {
    std::vector<GridCase> cases;
    int k = 0;
    for (float roughness : {0.2f, 0.5f, 1.0f})
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float specular : {1.0f, 0.3f}) {
                const glm::vec3 colour = (k % 3 == 2) ? glm::vec3(2.0f, 1.0f, 0.2f) : glm::vec3(1.0f);
                const float coat = (k % 4 == 1) ? 1.0f : (k % 4 == 3 ? 0.5f : 0.0f);
                const float sheen = (k % 3 == 1) ? 1.0f : 0.0f;
                const bool coatNormal = k % 8 == 5 || k % 8 == 7;
                // (Coats fall on odd k, at cos 0.25: the tilted ones are seen at 0.8.)
                cases.push_back({roughness, metallic, specular, colour, (k % 2 && !coatNormal) ? 0.25f : 0.8f, coat,
                                 sheen, coatNormal});
                ++k;
            }
    return cases;
}

BsdfParams gridParams(const GridCase& c) {
    BsdfParams p = makeBsdfParams(glm::vec3(0.8f, 0.6f, 0.3f), c.metallic, c.roughness);
    p.specular = c.specular;
    p.specularColor = c.specularColor;
    p.clearcoat = c.clearcoat;
    p.clearcoatRoughness = 0.3f;
    p.sheenColor = glm::vec3(0.7f, 0.5f, 0.9f) * c.sheen;
    p.sheenRoughness = 0.5f;
    if (c.coatNormal) {
        p.clearcoatNormal = glm::normalize(glm::vec3(0.35f, -0.2f, 0.9f));
        p.flags |= kBsdfCoatNormal;
    }
    return p;
}

TEST(Bsdf, SamplingMatchesPdfOverParameterGrid) {
    const std::vector<GridCase> cases = gridCases();
    // Sidak-corrected 1% significance over the grid.
    const double significance = 1.0 - std::pow(0.99, 1.0 / cases.size());
    uint32_t seed = 100;
    for (const GridCase& c : cases) {
        const BsdfParams p = gridParams(c);
        const glm::vec3 wo = direction(c.cosWo, 0.3f);
        std::mt19937 rng(seed++);
        std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
        int mismatches = 0;
        const auto r = test::chiSquareSphere(
            [&](int, glm::vec3& w) {
                const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
                if (s.lobe == kLobeNone) return false;
                w = s.wi;
                const float pdf = pdfBsdf(p, wo, s.wi);
                const glm::vec3 weight = evalBsdf(p, wo, s.wi) * s.wi.z / pdf;
                if (std::abs(s.pdf - pdf) > 1e-3f * pdf + 1e-5f ||
                    glm::any(glm::greaterThan(glm::abs(s.weight - weight), 1e-3f * weight + 1e-5f)))
                    ++mismatches;
                return true;
            },
            [&](const glm::vec3& w) { return static_cast<double>(pdfBsdf(p, wo, w)); }, 100000);
        EXPECT_EQ(mismatches, 0) << describe(c);
        EXPECT_GT(r.pValue, significance) << describe(c) << ": " << r.details;
    }
}


// The same grid sampled by the GPU build of sampleBsdf (lavapipe): its directions against the C++
// pdfBsdf (chi-square), so the shaders' sampling, not only the host's, follows the pdf that MIS
// and the photon estimates use.
class BsdfGpu : public test::GpuTest {};

std::vector<glm::vec4> sampleOnGpu(const BsdfParams& p, glm::vec3 wo, const std::vector<glm::vec4>& randoms) {
    vk::Context& context = test::gpu();
    const std::vector<BsdfSamplingCase> testCase{{p, glm::vec4(wo, 0.0f)}};
    vk::Buffer caseBuffer = vk::makeStorageBuffer(context, "bsdf sampling case", testCase);
    vk::Buffer random = vk::makeStorageBuffer(context, "bsdf sampling randoms", randoms);
    vk::Buffer out(context, "bsdf samples", randoms.size() * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer tables = makeBsdfTablesBuffer(context);
    vk::Kernel<BsdfSamplingKernel> kernel(context);
    kernel.bind(kBsdfSamplingCaseBinding, caseBuffer);
    kernel.bind(kBsdfSamplingRandomBinding, random);
    kernel.bind(kBsdfSamplingOutputBinding, out);
    kernel.bind(kBsdfSamplingTablesBinding, tables);
    const uint32_t count = static_cast<uint32_t>(randoms.size());
    context.submitAndWait([&](VkCommandBuffer cmd) {
        kernel.record(cmd, count, count);
        vk::computeToHostBarrier(cmd);
    });
    return out.download<glm::vec4>();
}

TEST_F(BsdfGpu, SamplingMatchesPdfOverParameterGrid) {
    const std::vector<GridCase> cases = gridCases();
    const double significance = 1.0 - std::pow(0.99, 1.0 / cases.size());
    constexpr int kSamples = 100000;
    uint32_t seed = 500;
    for (const GridCase& c : cases) {
        const BsdfParams p = gridParams(c);
        const glm::vec3 wo = direction(c.cosWo, 0.3f);
        std::mt19937 rng(seed++);
        std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
        std::vector<glm::vec4> randoms(kSamples);
        for (glm::vec4& r : randoms) r = glm::vec4(u(rng), u(rng), u(rng), 0.0f);
        const std::vector<glm::vec4> samples = sampleOnGpu(p, wo, randoms);
        const auto r = test::chiSquareSphere(
            [&](int i, glm::vec3& w) {
                if (samples[i].w == 0.0f) return false;
                w = glm::normalize(glm::vec3(samples[i]));
                return true;
            },
            [&](const glm::vec3& w) { return static_cast<double>(pdfBsdf(p, wo, w)); }, kSamples);
        EXPECT_GT(r.pValue, significance) << describe(c) << ": " << r.details;
    }
}

// The GPU test can fail: the GPU's samples of one material against another's pdf.
TEST_F(BsdfGpu, ChiSquareRejectsAnotherMaterialsSamples) {
    const GridCase c = gridCases()[4];  // a rough-0.2 metal: the lobe is the whole distribution
    ASSERT_EQ(c.metallic, 1.0f);
    BsdfParams sampled = gridParams(c);
    BsdfParams claimed = sampled;
    claimed.roughness = sampled.roughness * 1.5f;
    const glm::vec3 wo = direction(c.cosWo, 0.3f);
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    std::vector<glm::vec4> randoms(100000);
    for (glm::vec4& r : randoms) r = glm::vec4(u(rng), u(rng), u(rng), 0.0f);
    const std::vector<glm::vec4> samples = sampleOnGpu(sampled, wo, randoms);
    const auto r = test::chiSquareSphere(
        [&](int i, glm::vec3& w) {
            if (samples[i].w == 0.0f) return false;
            w = glm::normalize(glm::vec3(samples[i]));
            return true;
        },
        [&](const glm::vec3& w) { return static_cast<double>(pdfBsdf(claimed, wo, w)); }, 100000);
    EXPECT_LT(r.pValue, 1e-6) << r.details;
}

}  // namespace
}  // namespace vkp
