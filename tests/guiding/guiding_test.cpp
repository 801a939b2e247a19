// The photon-guided sampling grid (shaders/shared/guiding.glsl) on the host: its pdf integrates to
// one, matches what it samples (chi-square), puts more samples where more flux arrives, and gives
// every direction a non-zero density; guide-driven Russian roulette never gives a path zero odds.
#include <cmath>
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/chi_square.h"
#include "shared/guiding.glsl"
#include "shared/halton.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

constexpr double kSignificance = 0.001;

struct Grid {
    float cdf[kMaxGuideCells] = {};
    uint32_t m, n;
};

// A grid built from photons concentrated around one direction, plus a few strays.
Grid peakedGrid(uint32_t m, uint32_t n, uint32_t seed) {
    Grid g{{}, m, n};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 peak = glm::normalize(glm::vec3(0.6f, 0.2f, 0.4f));
    for (int i = 0; i < 60; ++i) {
        glm::vec3 w = i % 10 == 0 ? sampleCosineHemisphere({u(rng), u(rng)})
                                  : glm::normalize(peak + 0.2f * glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f));
        guideAdd(g.cdf, m, n, w, 0.5f + u(rng));
    }
    guideFinalize(g.cdf, m, n);
    return g;
}

TEST(Guiding, PdfIntegratesToOne) {
    for (auto [m, n] : {std::pair{4u, 16u}, std::pair{8u, 8u}, std::pair{2u, 4u}}) {
        const Grid g = peakedGrid(m, n, 1);
        // Over the unit square of the cosine mapping, d omega = du dv pi / cos(theta) (u = sin^2
        // theta, phi = 2 pi v); a midpoint grid aligned with every cell integrates exactly.
        double integral = 0.0;
        const int steps = 256;
        for (int i = 0; i < steps; ++i)
            for (int j = 0; j < steps; ++j) {
                const glm::vec3 w = sampleCosineHemisphere({(i + 0.5f) / steps, (j + 0.5f) / steps});
                integral += guidePdf(g.cdf, m, n, w) * kPi / w.z / (double(steps) * steps);
            }
        EXPECT_NEAR(integral, 1.0, 1e-4) << m << "x" << n;
        EXPECT_FLOAT_EQ(g.cdf[m * n - 1], 1.0f);
    }
}

TEST(Guiding, SamplingMatchesThePdf) {
    const Grid g = peakedGrid(4, 16, 2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) { w = guideSample(g.cdf, g.m, g.n, {u(rng), u(rng)}); return true; },
        [&](const glm::vec3& w) { return double(guidePdf(g.cdf, g.m, g.n, w)); }, 200000, 16, 32, 128);
    EXPECT_GT(r.pValue, kSignificance) << r.details;
}

// A stratified set of 2-D points stays stratified through the grid: each cell gets its share of
// the points to within one, and inside the cell that gets the most, the points spread evenly
// over both of its coordinates (a cell chosen by a number of its own would scatter them at random).
TEST(Guiding, StratifiedPointsStayStratified) {
    const Grid g = peakedGrid(4, 16, 2);
    const uint32_t count = 4096;
    std::vector<uint32_t> perCell(kMaxGuideCells, 0);
    std::vector<glm::vec2> inCell[kMaxGuideCells];
    for (uint32_t i = 0; i < count; ++i) {
        // Hammersley's net: i / N against the base-2 radical inverse of i (its digits scrambled by
        // a fixed permutation per position, which keeps the net).
        const glm::vec2 point{(float(i) + 0.5f) / float(count), scrambledRadicalInverse(2u, i, 0u)};
        const glm::vec3 w = guideSample(g.cdf, g.m, g.n, point);
        const glm::vec2 square = invertCosineHemisphere(w);
        const uint32_t c = guideCell(square, g.m, g.n);
        perCell[c] += 1;
        inCell[c].push_back({square.x * g.m - float(c / g.n), square.y * g.n - float(c % g.n)});
    }
    uint32_t fullest = 0;
    for (uint32_t c = 0; c < g.m * g.n; ++c) {
        const double share = count * double(guideCellProbability(g.cdf, c));
        EXPECT_NEAR(perCell[c], share, 1.01) << "cell " << c;
        if (perCell[c] > perCell[fullest]) fullest = c;
    }
    const auto& points = inCell[fullest];
    ASSERT_GE(points.size(), 256u);
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<uint32_t> bins(8, 0);
        for (const glm::vec2& p : points) bins[std::min(7u, uint32_t(std::clamp(p[axis], 0.0f, 1.0f) * 8.0f))] += 1;
        for (uint32_t b = 0; b < 8; ++b)
            EXPECT_NEAR(bins[b], points.size() / 8.0, 2.01) << "axis " << axis << " bin " << b << " of " << points.size();
    }
}

// The chi-square test can fail: the guided sampler checked against the plain cosine pdf.
TEST(Guiding, ChiSquareRejectsTheCosinePdf) {
    const Grid g = peakedGrid(4, 16, 2);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, kOneMinusEpsilon);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) { w = guideSample(g.cdf, g.m, g.n, {u(rng), u(rng)}); return true; },
        [&](const glm::vec3& w) { return double(cosineHemispherePdf(w.z)); }, 300000);
    EXPECT_LT(r.pValue, 1e-6) << r.details;
}

TEST(Guiding, FollowsTheFluxAndNeverVanishes) {
    const Grid g = peakedGrid(4, 16, 5);
    const glm::vec3 peak = glm::normalize(glm::vec3(0.6f, 0.2f, 0.4f));
    const glm::vec3 away = glm::normalize(glm::vec3(-0.6f, -0.2f, 0.4f));
    EXPECT_GT(guidePdf(g.cdf, 4, 16, peak), 5.0f * cosineHemispherePdf(peak.z));
    EXPECT_GT(guidePdf(g.cdf, 4, 16, away), 0.0f);
    EXPECT_EQ(guidePdf(g.cdf, 4, 16, glm::vec3(0.0f, 0.0f, -1.0f)), 0.0f);
    // An empty grid is the cosine distribution.
    Grid empty{{}, 4, 16};
    guideFinalize(empty.cdf, 4, 16);
    EXPECT_NEAR(guidePdf(empty.cdf, 4, 16, peak), cosineHemispherePdf(peak.z), 1e-5f);
}

// Adaptive resolution: a sparse grid is coarsened into unions of its cells (the energy of each
// direction stays where it was), a well-filled one is kept, and the result is still a pdf.
TEST(Guiding, CoarsensSparseGridsIntoUnionsOfCells) {
    EXPECT_EQ(guideAdaptiveSize(4, 16, 2, 200.0f), glm::uvec2(4, 16));
    EXPECT_EQ(guideAdaptiveSize(4, 16, 2, 100.0f), glm::uvec2(4, 8));
    EXPECT_EQ(guideAdaptiveSize(4, 16, 2, 0.0f), glm::uvec2(2, 4));
    EXPECT_EQ(guideAdaptiveSize(3, 5, 4, 0.0f), glm::uvec2(3, 5));  // nothing halves evenly
    float fine[kMaxGuideCells] = {};
    float coarse[kMaxGuideCells] = {};
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 w = sampleCosineHemisphere({u(rng), u(rng)});
        const float energy = 0.5f + u(rng);
        guideAdd(fine, 4, 16, w, energy);
        guideAdd(coarse, 2, 4, w, energy);
    }
    guideCoarsen(fine, 4, 16, 2, 4);
    for (uint32_t c = 0; c < kMaxGuideCells; ++c) EXPECT_NEAR(fine[c], coarse[c], 1e-4f) << c;
    guideFinalize(fine, 2, 4);
    double integral = 0.0;
    const int steps = 256;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const glm::vec3 w = sampleCosineHemisphere({(i + 0.5f) / steps, (j + 0.5f) / steps});
            integral += guidePdf(fine, 2, 4, w) / cosineHemispherePdf(w.z) / (steps * steps);
        }
    EXPECT_NEAR(integral, 1.0, 1e-3);
}

// Inside the weight window (from 2 / (1 + s) of the reference up) a path goes on; below it, it
// survives with the ratio, never less than the floor; without a reference nothing is decided.
TEST(Guiding, RouletteSurvivalFollowsTheWeightWindow) {
    const float lower = 2.0f / (1.0f + kGuideRouletteWindow);
    EXPECT_EQ(guideSurvival(lower, 1.0f), 1.0f);
    EXPECT_EQ(guideSurvival(5.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(guideSurvival(0.5f * lower, 1.0f), 0.5f * lower);
    EXPECT_FLOAT_EQ(guideSurvival(0.5f * lower * 8.0f, 8.0f), 0.5f * lower);
    EXPECT_EQ(guideSurvival(0.0f, 1.0f), kGuideRouletteMinSurvival);
    EXPECT_GT(kGuideRouletteMinSurvival, 0.0f);
    EXPECT_EQ(guideSurvival(1.0f, 0.0f), 1.0f);
    EXPECT_EQ(guideSurvival(std::nanf(""), 1.0f), 1.0f);
}

}  // namespace
}  // namespace vkp
