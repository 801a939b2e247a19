// KHR_materials_anisotropy in the shared BSDF (host build; SharedFunctions.AnisotropicBsdfMatches
// compares the GPU build): strength 0 is the isotropic BSDF bit for bit, the anisotropic GGX
// distribution and its visible normals are normalised (closed form: both integrate to 1), the
// sampler follows the pdf (chi-square), its weights are f cos / pdf, the lobe is stretched along
// the direction it is given, and a white rough metal reflects what quadrature of f says.
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "support/chi_square.h"
#include "support/local_directions.h"
#include "shared/bsdf.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

using test::sameBits;

glm::vec3 direction(float cosTheta, float phi) { return test::localDirection(cosTheta, phi); }

BsdfParams anisotropic(float roughness, float metallic, float strength, float angle) {
    BsdfParams p = makeBsdfParams(glm::vec3(0.9f, 0.7f, 0.4f), metallic, roughness);
    p.anisotropy = strength;
    p.anisotropyDirection = glm::vec2(std::cos(angle), std::sin(angle));
    return p;
}

// Strength 0 with any direction gives exactly the bits of the material without the extension:
// evaluation, pdf and sampling, over random materials (coats, sheen, specular colour) and directions.
TEST(BsdfAnisotropy, StrengthZeroIsIsotropicBitForBit) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (int i = 0; i < 20000; ++i) {
        BsdfParams plain = makeBsdfParams(glm::vec3(u(rng), u(rng), u(rng)), u(rng) < 0.5f ? 0.0f : u(rng), u(rng));
        plain.clearcoat = u(rng) < 0.3f ? u(rng) : 0.0f;
        plain.sheenColor = u(rng) < 0.3f ? glm::vec3(u(rng)) : glm::vec3(0.0f);
        plain.specularColor = glm::vec3(1.0f, 2.0f * u(rng), 1.0f);
        BsdfParams zero = plain;
        zero.anisotropy = 0.0f;
        zero.anisotropyDirection = glm::normalize(glm::vec2(u(rng) - 0.5f, u(rng) - 0.5f) + 1e-3f);
        const glm::vec3 wo = direction(0.01f + 0.99f * u(rng), 6.28f * u(rng));
        const glm::vec3 wi = direction(0.01f + 0.99f * u(rng), 6.28f * u(rng));
        ASSERT_TRUE(sameBits(evalBsdf(plain, wo, wi), evalBsdf(zero, wo, wi))) << i;
        ASSERT_TRUE(sameBits(pdfBsdf(plain, wo, wi), pdfBsdf(zero, wo, wi))) << i;
        const glm::vec3 r(u(rng), u(rng), u(rng));
        const BsdfSample a = sampleBsdf(plain, wo, true, true, r), b = sampleBsdf(zero, wo, true, true, r);
        ASSERT_TRUE(sameBits(a.wi, b.wi) && sameBits(a.weight, b.weight) && sameBits(a.pdf, b.pdf)) << i;
    }
}

// The anisotropic functions with alpha_t = alpha_b are the isotropic ones (to rounding).
TEST(BsdfAnisotropy, EqualAlphasAreTheIsotropicLobe) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (int i = 0; i < 10000; ++i) {
        const float alpha = 0.02f + 0.98f * u(rng);
        const glm::vec3 wo = direction(0.05f + 0.95f * u(rng), 6.28f * u(rng));
        const glm::vec3 wi = direction(0.05f + 0.95f * u(rng), 6.28f * u(rng));
        const glm::vec2 a(alpha, alpha);
        EXPECT_NEAR(ggxReflectionAnisotropic(wo, wi, a), ggxReflection(wo, wi, alpha), 1e-4f * ggxReflection(wo, wi, alpha) + 1e-6f);
        EXPECT_NEAR(ggxReflectionPdfAnisotropic(wo, wi, a), ggxReflectionPdf(wo, wi, alpha),
                    1e-4f * ggxReflectionPdf(wo, wi, alpha) + 1e-6f);
    }
}

// Closed form: integral of D(h) h.z over the hemisphere = 1, and of the visible-normal density
// G1(wo) max(0, wo.h) D(h) / wo.z = 1 (Heitz 2014), for stretched lobes in several directions.
TEST(BsdfAnisotropy, DistributionAndVisibleNormalsIntegrateToOne) {
    for (const glm::vec2 a : {glm::vec2(0.5f, 0.1f), glm::vec2(1.0f, 0.25f), glm::vec2(0.3f, 0.3f), glm::vec2(0.8f, 0.05f)})
        for (const float cosWo : {1.0f, 0.6f, 0.2f})
            for (const float phiWo : {0.0f, 0.9f, 1.5708f}) {
                const glm::vec3 wo = direction(cosWo, phiWo);
                // Midpoint rule over (t, phi) with cos theta = 1 - t^2 (nodes dense at the pole).
                constexpr int kSteps = 1500;
                double area = 0.0, visible = 0.0;
                for (int i = 0; i < kSteps; ++i) {
                    const double t = (i + 0.5) / kSteps;
                    const double mu = 1.0 - t * t;
                    for (int j = 0; j < kSteps; ++j) {
                        const double phi = 2.0 * kPi * (j + 0.5) / kSteps;
                        const glm::vec3 h = direction(static_cast<float>(mu), static_cast<float>(phi));
                        const double d = ggxDAnisotropic(h, a);
                        const double weight = 2.0 * t / kSteps * 2.0 * kPi / kSteps;  // d(mu) dphi
                        area += d * mu * weight;
                        visible += ggxG1Anisotropic(wo, a) * std::max(0.0f, glm::dot(wo, h)) * d / wo.z * weight;
                    }
                }
                EXPECT_NEAR(area, 1.0, 5e-3) << a.x << "," << a.y;
                EXPECT_NEAR(visible, 1.0, 5e-3) << a.x << "," << a.y << " cos " << cosWo << " phi " << phiWo;
            }
}

struct Case {
    float roughness, metallic, strength, angle, cosWo, phiWo;
};

std::string describe(const Case& c) {
    std::ostringstream s;
    s << "roughness " << c.roughness << " metallic " << c.metallic << " strength " << c.strength << " angle "
      << c.angle << " cos " << c.cosWo << " phi " << c.phiWo;
    return s.str();
}

// sampleBsdf's directions follow pdfBsdf (chi-square over the sphere), and every sample's pdf and
// weight are pdfBsdf's and evalBsdf cos / pdf.
TEST(BsdfAnisotropy, SamplingMatchesPdf) {
    const std::vector<Case> cases = {
        {0.3f, 1.0f, 0.5f, 0.0f, 0.8f, 0.3f},  {0.3f, 1.0f, 1.0f, 1.0f, 0.5f, 2.0f},
        {0.5f, 1.0f, 0.8f, 2.5f, 0.3f, 0.0f},  {0.2f, 0.0f, 0.7f, 0.5f, 0.8f, 1.0f},
        {0.6f, 0.5f, 1.0f, 4.0f, 0.6f, -1.0f}, {0.15f, 1.0f, 0.9f, 0.0f, 0.9f, 1.57f},
    };
    const double significance = 1.0 - std::pow(0.99, 1.0 / cases.size());
    uint32_t seed = 40;
    for (const Case& c : cases) {
        const BsdfParams p = anisotropic(c.roughness, c.metallic, c.strength, c.angle);
        const glm::vec3 wo = direction(c.cosWo, c.phiWo);
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
            [&](const glm::vec3& w) { return static_cast<double>(pdfBsdf(p, wo, w)); }, 100000, 16, 32, 24);
        EXPECT_EQ(mismatches, 0) << describe(c);
        EXPECT_GT(r.pValue, significance) << describe(c) << ": " << r.details;
    }
}

// The test can fail: samples of a lobe stretched along x against the pdf of one stretched along y.
TEST(BsdfAnisotropy, ChiSquareRejectsARotatedLobe) {
    const BsdfParams sampled = anisotropic(0.3f, 1.0f, 0.8f, 0.0f);
    const BsdfParams claimed = anisotropic(0.3f, 1.0f, 0.8f, 1.5708f);
    const glm::vec3 wo = direction(0.8f, 0.4f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) {
            const BsdfSample s = sampleBsdf(sampled, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
            w = s.wi;
            return s.lobe != kLobeNone;
        },
        [&](const glm::vec3& w) { return static_cast<double>(pdfBsdf(claimed, wo, w)); }, 100000);
    EXPECT_LT(r.pValue, 1e-6) << r.details;
}

// The highlight spreads along the anisotropy direction: seen and lit from the normal, a light
// tilted 30 degrees along the direction is reflected more strongly than one tilted across it
// (alpha_t > alpha_b), and rotating the direction by 90 degrees swaps the two.
TEST(BsdfAnisotropy, LobeIsStretchedAlongItsDirection) {
    for (const float angle : {0.0f, 0.7f, 2.0f}) {
        const BsdfParams p = anisotropic(0.2f, 1.0f, 0.8f, angle);
        const glm::vec3 wo(0.0f, 0.0f, 1.0f);
        const glm::vec3 along = direction(std::cos(0.5236f), angle);
        const glm::vec3 across = direction(std::cos(0.5236f), angle + 1.5708f);
        EXPECT_GT(evalBsdf(p, wo, along).x, 5.0f * evalBsdf(p, wo, across).x) << angle;
        const BsdfParams turned = anisotropic(0.2f, 1.0f, 0.8f, angle + 1.5708f);
        EXPECT_NEAR(evalBsdf(turned, wo, across).x, evalBsdf(p, wo, along).x, 1e-3f * evalBsdf(p, wo, along).x);
    }
}

// White furnace of a white anisotropic metal without energy compensation: the mean sample weight
// (sampling) equals the quadrature of evalBsdf (an independent integral), and is below 1.
TEST(BsdfAnisotropy, WhiteMetalFurnaceSamplingMatchesQuadrature) {
    for (const float strength : {0.5f, 1.0f})
        for (const float cosWo : {0.9f, 0.4f}) {
            BsdfParams p = makeBsdfParams(glm::vec3(1.0f), 1.0f, 0.4f);
            p.anisotropy = strength;
            p.anisotropyDirection = glm::vec2(std::cos(0.6f), std::sin(0.6f));
            p.flags |= kBsdfNoEnergyCompensation;
            const glm::vec3 wo = direction(cosWo, 1.1f);
            std::mt19937 rng(11);
            std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
            double sampled = 0.0;
            constexpr int kSamples = 400000;
            for (int i = 0; i < kSamples; ++i) {
                const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
                if (s.lobe != kLobeNone) sampled += s.weight.x;
            }
            sampled /= kSamples;
            constexpr int kSteps = 1024;
            double integrated = 0.0;
            for (int i = 0; i < kSteps; ++i) {
                const double t = (i + 0.5) / kSteps;
                for (int j = 0; j < kSteps; ++j) {
                    const double phi = 2.0 * kPi * (j + 0.5) / kSteps;
                    const glm::vec3 wi = direction(static_cast<float>(t * t), static_cast<float>(phi));
                    integrated += evalBsdf(p, wo, wi).x * t * t * 2.0 * t;
                }
            }
            integrated *= (1.0 / kSteps) * (2.0 * kPi / kSteps);
            EXPECT_NEAR(sampled, integrated, 0.01 * integrated) << "strength " << strength << " cos " << cosWo;
            EXPECT_LT(integrated, 1.0);
            EXPECT_GT(integrated, 0.5);
        }
}

}  // namespace
}  // namespace vkp
