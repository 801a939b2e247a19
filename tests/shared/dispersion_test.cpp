// KHR_materials_dispersion's index by wavelength and the spectral basis paths take their colour
// from (shared/dispersion.glsl): the index at the d line is `ior`, the Abbe number comes out as
// 20 / dispersion, dispersion 0 is the plain index, and the RGB basis keeps white white.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "shared/dispersion.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

// The extension's definition: V = (n_d - 1) / (n_F - n_C) with the Fraunhofer d, F and C lines
// (587.6, 486.1, 656.3 nm), and dispersion = 20 / V.
TEST(Dispersion, IndexFollowsTheAbbeNumber) {
    for (const float ior : {1.5f, 1.7f, 2.4f})
        for (const float dispersion : {0.2f, 0.5f, 1.0f}) {
            EXPECT_NEAR(dispersiveIor(ior, dispersion, 587.6f), ior, 2e-4f);
            const float nF = dispersiveIor(ior, dispersion, 486.1f), nC = dispersiveIor(ior, dispersion, 656.3f);
            const float abbe = (ior - 1.0f) / (nF - nC);
            EXPECT_NEAR(abbe, 20.0f / dispersion, 0.005f * 20.0f / dispersion) << ior << " " << dispersion;
            EXPECT_GT(dispersiveIor(ior, dispersion, 420.0f), dispersiveIor(ior, dispersion, 700.0f));  // blue bends more
        }
}

TEST(Dispersion, ZeroIsThePlainIndex) {
    for (const float lambda : {380.0f, 500.0f, 779.0f}) {
        const float n = dispersiveIor(1.52f, 0.0f, lambda);
        EXPECT_EQ(n, 1.52f);
        EXPECT_EQ(dispersiveIor(0.0f, 0.5f, lambda), 0.0f);  // the infinite index stays infinite
    }
}

// Each channel of the basis integrates to 1 over [380, 780] nm, so the mean weight of a uniformly
// drawn wavelength is (1, 1, 1): white light split and gathered again is white. The channels peak
// in their own parts of the spectrum (red long, blue short).
TEST(Dispersion, BasisKeepsWhiteWhite) {
    constexpr int kSteps = 40000;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kSteps; ++i) sum += glm::dvec3(spectralWeight(sampleWavelength((i + 0.5f) / kSteps)));
    sum /= kSteps;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 1e-3) << c;
    const glm::vec3 red = spectralBasis(620.0f), green = spectralBasis(540.0f), blue = spectralBasis(450.0f);
    EXPECT_GT(red.x, 5.0f * red.z);
    EXPECT_GT(green.y, green.x);
    EXPECT_GT(blue.z, 5.0f * blue.x);
    EXPECT_EQ(spectralBasis(700.0f).z, 0.0f);
}

}  // namespace
}  // namespace vkp
