// KHR_materials_iridescence in the shared BSDF (host build; SharedFunctions.ThinFilmFresnelMatches
// and RoughDielectricFilmMatches compare the GPU build): no film (factor 0 or thickness 0) is the
// plain BSDF bit for bit, smooth and rough glass reflect the film's Fresnel and transmit the rest,
// and the thin-film reflectance at normal incidence matches an independent spectral computation.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "support/local_directions.h"
#include "shared/bsdf.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

using test::sameBits;

glm::vec3 direction(float cosTheta, float phi) { return test::localDirection(cosTheta, phi); }

// A material with factor 0 (any thickness), or thickness 0 (any factor; the extension's sample
// renderer turns the film off there), gives exactly the bits of the material without the extension.
TEST(BsdfIridescence, NoFilmIsThePlainBsdfBitForBit) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (int i = 0; i < 20000; ++i) {
        BsdfParams plain = makeBsdfParams(glm::vec3(u(rng), u(rng), u(rng)), u(rng) < 0.5f ? 0.0f : u(rng), u(rng));
        plain.clearcoat = u(rng) < 0.3f ? u(rng) : 0.0f;
        plain.specularColor = glm::vec3(1.0f, 2.0f * u(rng), 1.0f);
        plain.ior = u(rng) < 0.1f ? 0.0f : 1.0f + u(rng);
        BsdfParams noFactor = plain;
        noFactor.iridescence = 0.0f;
        noFactor.iridescenceIor = 1.0f + u(rng);
        noFactor.iridescenceThickness = 1000.0f * u(rng);
        BsdfParams noThickness = plain;
        noThickness.iridescence = u(rng);
        noThickness.iridescenceIor = 1.0f + u(rng);
        noThickness.iridescenceThickness = 0.0f;
        const glm::vec3 wo = direction(0.01f + 0.99f * u(rng), 6.28f * u(rng));
        const glm::vec3 wi = direction(0.01f + 0.99f * u(rng), 6.28f * u(rng));
        const glm::vec3 r(u(rng), u(rng), u(rng));
        const BsdfSample a = sampleBsdf(plain, wo, true, true, r);
        for (const BsdfParams& p : {noFactor, noThickness}) {
            ASSERT_TRUE(sameBits(evalBsdf(plain, wo, wi), evalBsdf(p, wo, wi))) << i;
            ASSERT_TRUE(sameBits(pdfBsdf(plain, wo, wi), pdfBsdf(p, wo, wi))) << i;
            const BsdfSample b = sampleBsdf(p, wo, true, true, r);
            ASSERT_TRUE(sameBits(a.wi, b.wi) && sameBits(a.weight, b.weight) && sameBits(a.pdf, b.pdf)) << i;
        }
    }
}

// The film changes the specular colour: a white dielectric with a 400 nm film of ior 1.3 reflects
// a different colour at the mirror direction than without, and the full factor's Fresnel is the film's.
TEST(BsdfIridescence, FilmReplacesTheSpecularFresnel) {
    BsdfParams p = makeBsdfParams(glm::vec3(0.5f), 0.0f, 0.3f);
    p.iridescence = 1.0f;
    p.iridescenceIor = 1.3f;
    p.iridescenceThickness = 400.0f;
    const float cosTheta = 0.8f;
    const glm::vec3 film = thinFilmFresnel(1.0f, 1.3f, cosTheta, 400.0f, glm::vec3(dielectricF0(1.5f)));
    const glm::vec3 fresnel = specularFresnel(p, cosTheta);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(fresnel[c], film[c]);
    EXPECT_GT(std::abs(film.x - film.z), 0.01f);  // coloured
}

// Smooth glass under a film, seen from outside: reflection carries the film's Fresnel and
// refraction the rest, tinted (the means of the sample weights over both branches, 1 %); from
// inside the film is not seen (the plain layer's bits).
TEST(BsdfIridescence, SmoothGlassReflectsTheFilmsFresnel) {
    BsdfParams glass = makeBsdfParams(glm::vec3(0.9f, 0.8f, 0.7f), 0.0f, 0.0f);
    glass.transmission = 1.0f;
    glass.iridescence = 1.0f;
    glass.iridescenceIor = 1.3f;
    glass.iridescenceThickness = 400.0f;
    const glm::vec3 wo = direction(0.7f, 0.4f);
    const glm::vec3 film = thinFilmFresnel(1.0f, 1.3f, 0.7f, 400.0f, glm::vec3(dielectricF0(1.5f)));
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    glm::dvec3 reflected(0.0), refracted(0.0);
    constexpr int kSamples = 400000;
    for (int i = 0; i < kSamples; ++i) {
        const BsdfSample s = sampleBsdf(glass, wo, true, false, glm::vec3(u(rng), u(rng), u(rng)));
        ((s.lobe & kLobeTransmission) != 0u ? refracted : reflected) += glm::dvec3(s.weight);
    }
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(reflected[c] / kSamples, film[c], 0.01 * film[c]) << c;
        EXPECT_NEAR(refracted[c] / kSamples, glass.baseColor[c] * (1.0f - film[c]), 0.01) << c;
    }
    BsdfParams plain = glass;
    plain.iridescence = 0.0f;
    const glm::vec3 r(0.3f, 0.6f, 0.2f);
    const BsdfSample a = sampleBsdf(glass, wo, false, true, r), b = sampleBsdf(plain, wo, false, true, r);
    EXPECT_TRUE(sameBits(a.wi, b.wi) && sameBits(a.weight, b.weight));
}

BsdfParams roughFilmGlass(float roughness, bool thin, float factor) {
    BsdfParams p = makeBsdfParams(glm::vec3(1.0f), 0.0f, roughness);
    p.transmission = 1.0f;
    p.thinWalled = thin ? 1u : 0u;
    p.iridescence = factor;
    p.iridescenceIor = 1.3f;
    p.iridescenceThickness = 400.0f;
    return p;
}

// Rough glass with factor 0 (any thickness) or thickness 0 is the plain rough dielectric layer bit
// for bit: its samples, eval and pdf, which are sampleRoughDielectric's, evalRoughDielectric's and
// pdfRoughDielectric's.
TEST(BsdfIridescence, RoughGlassWithoutFilmIsThePlainLayerBitForBit) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    for (int i = 0; i < 20000; ++i) {
        BsdfParams plain = makeBsdfParams(glm::vec3(u(rng), u(rng), u(rng)), 0.0f, 0.05f + 0.95f * u(rng));
        plain.transmission = 1.0f;
        plain.thinWalled = u(rng) < 0.3f ? 1u : 0u;
        plain.ior = 1.01f + u(rng);
        BsdfParams noFactor = plain;
        noFactor.iridescence = 0.0f;
        noFactor.iridescenceIor = 1.0f + u(rng);
        noFactor.iridescenceThickness = 1000.0f * u(rng);
        BsdfParams noThickness = plain;
        noThickness.iridescence = 0.1f + 0.9f * u(rng);
        noThickness.iridescenceThickness = 0.0f;
        const bool entering = u(rng) < 0.8f;
        const glm::vec3 wo = direction(0.01f + 0.99f * u(rng), 6.28f * u(rng));
        const glm::vec3 r(u(rng), u(rng), u(rng));
        const BsdfSample a = sampleBsdf(plain, wo, entering, true, r);
        const float eta = dielectricEta(plain, entering);
        float w;
        const glm::vec3 wi = sampleRoughDielectric(wo, bsdfAlpha(plain), eta, plain.thinWalled != 0u, false, true, r, w);
        if (a.lobe != kLobeNone) {
            ASSERT_TRUE(sameBits(a.wi, wi)) << i;
            ASSERT_TRUE(sameBits(a.weight, (wi.z < 0.0f ? plain.baseColor : glm::vec3(1.0f)) * w)) << i;
        }
        const float f = evalRoughDielectric(wo, a.wi, bsdfAlpha(plain), eta, plain.thinWalled != 0u, false, true);
        ASSERT_TRUE(sameBits(evalDielectricLayer(plain, wo, a.wi, entering, true),
                             a.wi.z < 0.0f ? plain.baseColor * f : glm::vec3(f))) << i;
        ASSERT_TRUE(sameBits(pdfDielectricLayer(plain, wo, a.wi, entering),
                             pdfRoughDielectric(wo, a.wi, bsdfAlpha(plain), eta, plain.thinWalled != 0u, false))) << i;
        for (const BsdfParams& p : {noFactor, noThickness}) {
            const BsdfSample b = sampleBsdf(p, wo, entering, true, r);
            ASSERT_TRUE(sameBits(a.wi, b.wi) && sameBits(a.weight, b.weight) && a.lobe == b.lobe) << i;
            ASSERT_TRUE(sameBits(evalDielectricLayer(plain, wo, a.wi, entering, true),
                                 evalDielectricLayer(p, wo, a.wi, entering, true))) << i;
            ASSERT_TRUE(sameBits(pdfDielectricLayer(plain, wo, a.wi, entering), pdfDielectricLayer(p, wo, a.wi, entering)))
                << i;
        }
    }
}

// Rough glass under a film, seen from outside: every sample's weight is the layer's eval |cos| /
// pdf per channel (so sampling by the mean Fresnel is unbiased), and the film colours the reflection.
TEST(BsdfIridescence, RoughGlassFilmSamplesMatchEvalOverPdf) {
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        BsdfParams p = roughFilmGlass(0.1f + 0.9f * u(rng), u(rng) < 0.3f, 0.2f + 0.8f * u(rng));
        p.baseColor = glm::vec3(0.9f, 0.8f, 0.7f);
        p.ior = 1.1f + u(rng);
        p.iridescenceThickness = 100.0f + 900.0f * u(rng);
        const glm::vec3 wo = direction(0.05f + 0.95f * u(rng), 6.28f * u(rng));
        const bool radiance = u(rng) < 0.5f;
        const BsdfSample s = sampleBsdf(p, wo, true, radiance, glm::vec3(u(rng), u(rng), u(rng)));
        if (s.lobe == kLobeNone) continue;
        const float pdf = pdfDielectricLayer(p, wo, s.wi, true);
        ASSERT_GT(pdf, 0.0f) << i;
        const glm::vec3 expected = evalDielectricLayer(p, wo, s.wi, true, radiance) * std::abs(s.wi.z) / pdf;
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(s.weight[c], expected[c], 2e-3f * expected[c] + 1e-5f) << i << " " << c;
        ++checked;
    }
    EXPECT_GT(checked, 18000);
}

// A white furnace for non-absorbing rough glass under a film (factor 1, ior 1.3, 400 nm), from
// outside: reflected plus transmitted energy per channel within the plain rough glass's bounds
// (BsdfTransmission.RoughGlassWhiteFurnace: at most 1 + 0.5 %, at least 0.95 at roughness 0.3 and
// 0.3 at roughness 1, equal to a quadrature of evalDielectricLayer within 1.5 %), while the
// reflected part alone is coloured (its channels differ) and differs from the plain glass's.
TEST(BsdfIridescence, RoughGlassFilmWhiteFurnace) {
    for (float roughness : {0.3f, 1.0f})
        for (bool thin : {false, true})
            for (float cosWo : {0.9f, 0.4f}) {
                const BsdfParams p = roughFilmGlass(roughness, thin, 1.0f);
                const BsdfParams plain = roughFilmGlass(roughness, thin, 0.0f);
                const glm::vec3 wo = direction(cosWo, 0.0f);
                std::mt19937 rng(5);
                std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
                const int n = 200000;
                glm::dvec3 total(0.0), reflected(0.0), plainReflected(0.0);
                for (int i = 0; i < n; ++i) {
                    const glm::vec3 r(u(rng), u(rng), u(rng));
                    const BsdfSample s = sampleBsdf(p, wo, true, false, r);
                    if (s.lobe != kLobeNone) total += glm::dvec3(s.weight);
                    if (s.lobe != kLobeNone && s.wi.z > 0.0f) reflected += glm::dvec3(s.weight);
                    const BsdfSample q = sampleBsdf(plain, wo, true, false, r);
                    if (q.lobe != kLobeNone && q.wi.z > 0.0f) plainReflected += glm::dvec3(q.weight);
                }
                total /= double(n);
                reflected /= double(n);
                plainReflected /= double(n);
                const glm::dvec3 quad = test::sphereQuadrature(512, [&](glm::vec3 wi, double mu) {
                    return glm::dvec3(evalDielectricLayer(p, wo, wi, true, false)) * mu;
                });
                for (int c = 0; c < 3; ++c) {
                    const std::string d = "roughness " + std::to_string(roughness) + (thin ? " thin" : " solid") +
                                          " cos " + std::to_string(cosWo) + " channel " + std::to_string(c) +
                                          ": sampled " + std::to_string(total[c]) + " quadrature " + std::to_string(quad[c]);
                    EXPECT_LT(total[c], 1.005) << d;
                    EXPECT_GT(total[c], roughness <= 0.3f ? 0.95 : 0.3) << d;
                    EXPECT_NEAR(total[c], quad[c], 0.015 * quad[c]) << d;
                }
                const double spread = std::max({reflected.x, reflected.y, reflected.z}) -
                                      std::min({reflected.x, reflected.y, reflected.z});
                EXPECT_GT(spread, 0.005) << "roughness " << roughness << " cos " << cosWo;
                EXPECT_GT(glm::length(reflected - plainReflected), 0.005) << "roughness " << roughness;
            }
}

// CIE 1931 2-degree matching function y-bar, by the multi-lobe fit of Wyman, Sloan & Shirley 2013,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions" (JCGT 2(2)): another fit
// than the one thinFilmSensitivity transforms.
double yBar(double lambda) {
    const auto g = [](double x, double mu, double s1, double s2) {
        const double t = (x - mu) / (x < mu ? s1 : s2);
        return std::exp(-0.5 * t * t);
    };
    return 0.821 * g(lambda, 568.8, 46.9, 40.5) + 0.286 * g(lambda, 530.9, 16.3, 31.1);
}

// Reflectance of a film (index n2, thickness d nm) on a substrate n3 seen from air at normal
// incidence, at wavelength lambda: the Airy sum in closed form, r = (r12 + r23 e^{i delta}) /
// (1 + r12 r23 e^{i delta}), delta = 4 pi n2 d / lambda, r_ij the Fresnel amplitude (n_i - n_j) / (n_i + n_j).
double airyReflectance(double n2, double n3, double d, double lambda) {
    const double r12 = (1.0 - n2) / (1.0 + n2), r23 = (n2 - n3) / (n2 + n3);
    const std::complex<double> e = std::polar(1.0, 4.0 * M_PI * n2 * d / lambda);
    return std::norm((r12 + r23 * e) / (1.0 + r12 * r23 * e));
}

// The luminance band Y = integral R(lambda) y-bar / integral y-bar of the exact spectrum, against
// the Y of thinFilmFresnel's linear sRGB (the Y row of sRGB to XYZ), at normal incidence over a
// substrate of ior 1.5 (F0 = 0.04), for films thinner and denser than it (both phase conventions).
// The extension's model keeps two orders of the Airy sum and another fit of the matching
// functions: 4 % apart at most here (measured up to 3.6 %, 0.0006 in absolute reflectance).
TEST(BsdfIridescence, NormalIncidenceMatchesTheAirySpectrum) {
    struct Film {
        double ior, thickness;
    };
    for (const Film f : {Film{1.3, 300.0}, Film{1.3, 500.0}, Film{2.0, 250.0}, Film{2.0, 400.0}, Film{1.8, 150.0}}) {
        double num = 0.0, den = 0.0;
        for (int i = 0; i < 3600; ++i) {
            const double lambda = 360.0 + (i + 0.5) * 0.125;
            num += airyReflectance(f.ior, 1.5, f.thickness, lambda) * yBar(lambda);
            den += yBar(lambda);
        }
        const double expected = num / den;
        const glm::vec3 rgb =
            thinFilmFresnel(1.0f, float(f.ior), 1.0f, float(f.thickness), glm::vec3(dielectricF0(1.5f)));
        const double y = 0.2126729 * rgb.x + 0.7151522 * rgb.y + 0.0721750 * rgb.z;
        EXPECT_NEAR(y, expected, 0.04 * expected) << "film ior " << f.ior << " thickness " << f.thickness;
    }
}

// The closed form can tell thicknesses apart: 300 and 500 nm films differ by far more than the
// tolerance above.
TEST(BsdfIridescence, ReflectanceDependsOnThickness) {
    const glm::vec3 base(dielectricF0(1.5f));
    const float a = luminance(thinFilmFresnel(1.0f, 1.3f, 1.0f, 300.0f, base));
    const float b = luminance(thinFilmFresnel(1.0f, 1.3f, 1.0f, 500.0f, base));
    EXPECT_GT(std::abs(a - b), 0.2f * std::max(a, b));
}

}  // namespace
}  // namespace vkp
