// The rough dielectric layer of KHR_materials_transmission (shared/bsdf_rough_dielectric.glsl,
// Walter et al. 2007), host build: chi-square of sampling against pdf (solid and thin-walled, both
// sides of the interface), sample weights against eval / pdf, the adjoint relation between the
// radiance and importance BTDFs, a white furnace, and chi-square of the whole mixture with
// transmission over a grid of the other lobes.
#include <cmath>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "support/chi_square.h"
#include "support/local_directions.h"
#include "shared/bsdf.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

glm::vec3 direction(float cosTheta, float phi) { return test::localDirection(cosTheta, phi); }

BsdfParams glass(float roughness, bool thin) {
    BsdfParams p = makeBsdfParams(glm::vec3(1.0f), 0.0f, roughness);
    p.transmission = 1.0f;
    p.thinWalled = thin ? 1u : 0u;
    return p;
}

// Sampling matches pdfDielectricLayer (chi-square over the whole sphere), and each sample's weight
// is evalDielectricLayer |cos| / pdf, over roughness x thin/solid x entering/leaving x angle.
TEST(BsdfTransmission, RoughDielectricSamplingMatchesPdf) {
    const float roughnesses[] = {0.3f, 0.6f, 1.0f};
    const int caseCount = 3 * 2 * 2 * 2;
    const double significance = 1.0 - std::pow(0.99, 1.0 / caseCount);
    uint32_t seed = 7;
    for (float roughness : roughnesses)
        for (bool thin : {false, true})
            for (bool entering : {true, false})
                for (float cosWo : {0.85f, 0.3f}) {
                    const BsdfParams p = glass(roughness, thin);
                    const glm::vec3 wo = direction(cosWo, 0.7f);
                    std::mt19937 rng(seed++);
                    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
                    int mismatches = 0;
                    const auto r = test::chiSquareSphere(
                        [&](int, glm::vec3& w) {
                            const BsdfSample s =
                                sampleBsdf(p, wo, entering, true, glm::vec3(u(rng), u(rng), u(rng)));
                            if (s.lobe == kLobeNone) return false;
                            w = s.wi;
                            const float pdf = pdfDielectricLayer(p, wo, s.wi, entering);
                            const glm::vec3 weight =
                                evalDielectricLayer(p, wo, s.wi, entering, true) * std::abs(s.wi.z) / pdf;
                            if (!(pdf > 0.0f) ||
                                glm::any(glm::greaterThan(glm::abs(s.weight - weight), 2e-3f * weight + 1e-5f)))
                                ++mismatches;
                            return true;
                        },
                        [&](const glm::vec3& w) { return static_cast<double>(pdfDielectricLayer(p, wo, w, entering)); },
                        100000, 16, 32, 32);
                    std::ostringstream d;
                    d << "roughness " << roughness << (thin ? " thin" : " solid") << (entering ? " entering" : " leaving")
                      << " cos " << cosWo;
                    EXPECT_EQ(mismatches, 0) << d.str();
                    EXPECT_GT(r.pValue, significance) << d.str() << ": " << r.details;
                }
}

// A solid of ior 1 is an invisible interface even when rough: every microfacet refracts wo to -wo,
// so the layer is a Dirac that passes the light straight through with weight 1 (white tint).
TEST(BsdfTransmission, RoughSolidOfIorOneIsInvisible) {
    BsdfParams p = glass(0.7f, false);
    p.ior = 1.0f;
    const glm::vec3 wo = direction(0.6f, 0.4f);
    for (float u : {0.1f, 0.5f, 0.9f}) {
        const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(0.5f, u, 1.0f - u));
        EXPECT_EQ(s.lobe, kLobeDelta | kLobeTransmission);
        EXPECT_NEAR(glm::length(s.wi + wo), 0.0f, 1e-5f);
        EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
    }
}

// Radiance and importance: the radiance BTDF through a solid's interface is the adjoint of the
// importance BTDF, f_radiance(wo -> wi, eta) = f_importance(-wi -> -wo, 1/eta) (Veach 1997, 5.2),
// so radiance entering glass is scaled by eta^2 = (n_wo / n_wi)^2 and importance is not. Reflection is
// reciprocal, f(wo, wi) = f(wi, wo), and the same in both modes.
TEST(BsdfTransmission, RadianceBtdfIsTheAdjointOfImportance) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    const float alpha = 0.3f;
    const float eta = 1.0f / 1.5f;
    int transmitted = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 wo = direction(std::max(u(rng), 0.02f), 6.28f * u(rng));
        const glm::vec3 wr = direction(std::max(u(rng), 0.02f), 6.28f * u(rng));
        const glm::vec3 wt = -direction(std::max(u(rng), 0.02f), 6.28f * u(rng));
        const float fr = evalRoughDielectric(wo, wr, alpha, eta, false, false, true);
        ASSERT_NEAR(fr, evalRoughDielectric(wr, wo, alpha, eta, false, false, true), 1e-4f * fr + 1e-6f);
        ASSERT_EQ(fr, evalRoughDielectric(wo, wr, alpha, eta, false, false, false));
        const float radiance = evalRoughDielectric(wo, wt, alpha, eta, false, false, true);
        const float importance = evalRoughDielectric(wo, wt, alpha, eta, false, false, false);
        const float adjoint = evalRoughDielectric(-wt, -wo, alpha, 1.0f / eta, false, false, false);
        ASSERT_NEAR(radiance, adjoint, 2e-3f * radiance + 2e-5f) << i;
        ASSERT_NEAR(radiance, importance * eta * eta, 1e-4f * radiance + 1e-7f);
        if (radiance > 0.0f) ++transmitted;
        // Thin walls do not bend: no eta^2 in either mode, and f(wo, wi) = f(-wi, -wo).
        const float thin = evalRoughDielectric(wo, wt, alpha, eta, true, false, true);
        ASSERT_EQ(thin, evalRoughDielectric(wo, wt, alpha, eta, true, false, false));
        ASSERT_NEAR(thin, evalRoughDielectric(-wt, -wo, alpha, eta, true, false, true), 1e-4f * thin + 1e-6f);
    }
    EXPECT_GT(transmitted, 200);
}

// White furnace of rough glass (importance mode, white tint): the mean sample weight is the
// energy the single-scattering BSDF keeps, reflection plus transmission. Tolerance: at least 0.95
// for roughness 0.3 and 0.3 at roughness 1, like a white metal's 1 - ln 2 = 0.307 at normal incidence
// (single-scattering GGX loses the light that
// scatters more than once between microfacets), never above 1 + 0.5 % (the sampling noise), and
// equal to a quadrature of evalDielectricLayer within 1.5 %.
TEST(BsdfTransmission, RoughGlassWhiteFurnace) {
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (bool thin : {false, true})
            for (bool entering : {true, false})
                for (float cosWo : {0.9f, 0.4f}) {
                    const BsdfParams p = glass(roughness, thin);
                    const glm::vec3 wo = direction(cosWo, 0.0f);
                    std::mt19937 rng(5);
                    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
                    const int n = 200000;
                    double sum = 0.0;
                    for (int i = 0; i < n; ++i) {
                        const BsdfSample s = sampleBsdf(p, wo, entering, false, glm::vec3(u(rng), u(rng), u(rng)));
                        if (s.lobe != kLobeNone) sum += s.weight.x;
                    }
                    const double sampled = sum / n;
                    // Quadrature over the sphere (mu = t^3 concentrates nodes at the horizon).
                    const double quad = test::sphereQuadrature(1024, [&](glm::vec3 wi, double mu) {
                        return evalDielectricLayer(p, wo, wi, entering, false).x * mu;
                    });
                    std::ostringstream d;
                    d << "roughness " << roughness << (thin ? " thin" : " solid") << (entering ? " entering" : " leaving")
                      << " cos " << cosWo << ": sampled " << sampled << " quadrature " << quad;
                    EXPECT_LT(sampled, 1.005) << d.str();
                    EXPECT_GT(sampled, roughness <= 0.3f ? 0.95 : 0.3) << d.str();
                    EXPECT_NEAR(sampled, quad, 0.015 * quad) << d.str();
                }
}

// The whole mixture with transmission 0.5 over a grid of the other lobes: the samples of
// sampleBsdf are distributed by pdfBsdf (the opaque layer, already weighted by 1 - transmission)
// plus transmission x pdfDielectricLayer.
TEST(BsdfTransmission, MixtureSamplingMatchesPdfOverParameterGrid) {
    struct Case {
        float roughness, metallic, specular, clearcoat, sheen;
    };
    std::vector<Case> cases;
    int k = 0;
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (float metallic : {0.0f, 0.5f})
            for (float specular : {1.0f, 0.4f}) {
                cases.push_back({roughness, metallic, specular, (k % 3 == 1) ? 0.8f : 0.0f, (k % 2) ? 1.0f : 0.0f});
                ++k;
            }
    const double significance = 1.0 - std::pow(0.99, 1.0 / (2.0 * cases.size()));
    uint32_t seed = 300;
    for (const Case& c : cases)
        for (float cosWo : {0.8f, 0.3f}) {
            BsdfParams p = makeBsdfParams(glm::vec3(0.8f, 0.6f, 0.3f), c.metallic, c.roughness);
            p.specular = c.specular;
            p.clearcoat = c.clearcoat;
            p.clearcoatRoughness = 0.3f;
            p.sheenColor = glm::vec3(0.7f, 0.5f, 0.9f) * c.sheen;
            p.sheenRoughness = 0.5f;
            p.transmission = 0.5f;
            p.thinWalled = (seed % 2) ? 1u : 0u;
            const glm::vec3 wo = direction(cosWo, 0.3f);
            std::mt19937 rng(seed++);
            std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
            const auto r = test::chiSquareSphere(
                [&](int, glm::vec3& w) {
                    const BsdfSample s = sampleBsdf(p, wo, true, true, glm::vec3(u(rng), u(rng), u(rng)));
                    if (s.lobe == kLobeNone) return false;
                    w = s.wi;
                    return true;
                },
                [&](const glm::vec3& w) {
                    return static_cast<double>(pdfBsdf(p, wo, w) + p.transmission * pdfDielectricLayer(p, wo, w, true));
                },
                100000, 16, 32, 32);
            EXPECT_GT(r.pValue, significance) << "roughness " << c.roughness << " metallic " << c.metallic
                                              << " specular " << c.specular << " coat " << c.clearcoat << " sheen "
                                              << c.sheen << " thin " << p.thinWalled << " cos " << cosWo << ": "
                                              << r.details;
        }
}

}  // namespace
}  // namespace vkp
