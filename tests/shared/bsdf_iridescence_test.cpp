// KHR_materials_iridescence in the shared BSDF (host build; SharedFunctions.ThinFilmFresnelMatches
// compares the GPU build): no film (factor 0 or thickness 0) is the plain BSDF bit for bit, and the
// thin-film reflectance at normal incidence matches an independent spectral computation.
#include <cmath>
#include <complex>
#include <cstring>
#include <random>

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
