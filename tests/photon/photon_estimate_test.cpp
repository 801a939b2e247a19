// Density-estimation kernels: the cone filter's normalisation integrates to the disk, the
// progressive radius update follows Hachisuka & Jensen's recurrences.
#include <cmath>

#include <gtest/gtest.h>

#include "shared/photon_estimate.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

TEST(ConeFilter, NormalizationMatchesTheDiskIntegral) {
    for (float k : {1.0f, 1.1f, 2.0f, 5.0f}) {
        // Integral over the disk of radius r of w(d) dA = 2 pi int_0^r (1 - d/(k r)) d dd.
        const float r = 0.7f;
        double integral = 0.0;
        const int steps = 100000;
        for (int i = 0; i < steps; ++i) {
            const double d = (i + 0.5) * r / steps;
            integral += 2.0 * M_PI * d * coneFilterWeight(static_cast<float>(d), r, k) * (r / steps);
        }
        EXPECT_NEAR(integral, coneFilterArea(r, k), 1e-4 * integral) << "k = " << k;
    }
    EXPECT_FLOAT_EQ(coneFilterWeight(0.0f, 1.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(coneFilterWeight(1.0f, 1.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(coneFilterWeight(2.0f, 1.0f, 1.0f), 0.0f);
}

TEST(ConeFilter, UniformDensityIsEstimatedExactly) {
    // Photons of power 1 spread uniformly (density rho per unit area): the filtered estimate of
    // the density is rho whatever k.
    const float rho = 1000.0f, r = 0.5f;
    for (float k : {1.0f, 1.5f, 3.0f}) {
        double sum = 0.0;
        const int grid = 600;
        const double cell = 2.0 * r / grid;
        for (int i = 0; i < grid; ++i)
            for (int j = 0; j < grid; ++j) {
                const double x = -r + (i + 0.5) * cell, y = -r + (j + 0.5) * cell;
                const double d = std::sqrt(x * x + y * y);
                if (d < r) sum += rho * cell * cell * coneFilterWeight(static_cast<float>(d), r, k);
            }
        EXPECT_NEAR(sum / coneFilterArea(r, k), rho, 2e-3 * rho) << "k = " << k;
    }
}

TEST(ProgressiveRadius, FollowsTheRecurrence) {
    float n = 0.0f, scale = 0.0f;
    float r2 = 1.0f;
    // First pass: 10 photons, alpha 0.7 -> n = 7, area ratio 7/10.
    r2 = progressiveRadiusUpdate(r2, n, 10.0f, 0.7f, scale);
    EXPECT_FLOAT_EQ(n, 7.0f);
    EXPECT_FLOAT_EQ(r2, 0.7f);
    EXPECT_FLOAT_EQ(scale, 0.7f);
    // Second pass: 10 more -> n = 14, ratio 14/17.
    r2 = progressiveRadiusUpdate(r2, n, 10.0f, 0.7f, scale);
    EXPECT_FLOAT_EQ(n, 14.0f);
    EXPECT_NEAR(r2, 0.7f * 14.0f / 17.0f, 1e-6f);
    // No photons: nothing changes.
    const float before = r2;
    r2 = progressiveRadiusUpdate(r2, n, 0.0f, 0.7f, scale);
    EXPECT_EQ(r2, before);
    EXPECT_EQ(scale, 1.0f);
}

TEST(ProgressiveRadius, ShrinksAtTheExpectedRate) {
    // With photons arriving in proportion to the disk's area (m = c r^2 per pass), r^2 decays like
    // pass^(alpha - 1) (Hachisuka & Jensen 2009, section 4.3) while n keeps growing.
    float n = 0.0f, scale = 0.0f, r2 = 1.0f;
    float previous = r2;
    for (int pass = 1; pass <= 1000; ++pass) {
        r2 = progressiveRadiusUpdate(r2, n, 20.0f * r2, 0.7f, scale);
        ASSERT_LT(r2, previous);
        previous = r2;
    }
    const float expected = std::pow(1000.0f, 0.7f - 1.0f);
    EXPECT_GT(r2, 0.5f * expected);
    EXPECT_LT(r2, 2.0f * expected);
    EXPECT_GT(n, 1000.0f);
}

}  // namespace
}  // namespace vkp
