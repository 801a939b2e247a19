// The viewer's device-side image (view/display_pass.h, shaders/render/display.comp): the linear
// resolve equals the host's (film mean plus SPPM's estimate) bit for bit, the 8-bit pixels follow
// the PNG's display transform (image/view_transform.h) to within the lattice's interpolation
// error, and the selection's outline and the surface's byte order are honoured.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "image/view_transform.h"
#include "render/film.h"
#include "shared/photon_render.glsl"
#include "support/gpu_test_support.h"
#include "view/display_pass.h"

namespace vkp {
namespace {

class DisplayPassTest : public test::GpuTest {
protected:
    static constexpr uint32_t kWidth = 64, kHeight = 48;

    // Runs the pass over `sums` (and `sppm`, when given) and returns the pixel words.
    std::vector<uint32_t> display(DisplayPass& pass, const std::vector<glm::vec4>& sums,
                                  const std::vector<gpu::SppmPixel>* sppm = nullptr, uint32_t passes = 1,
                                  float exposureScale = 1.0f, bool bgra = false) {
        const vk::Buffer film = vk::makeStorageBuffer(test::gpu(), "test film", sums);
        const vk::Buffer progressive = vk::makeStorageBuffer(test::gpu(), "test sppm",
                                                             sppm ? *sppm : std::vector<gpu::SppmPixel>{});
        test::gpu().submitAndWait([&](VkCommandBuffer cmd) {
            pass.record(cmd, film, sppm ? &progressive : nullptr, passes, exposureScale, bgra);
            vk::computeToHostBarrier(cmd);
        });
        return pass.pixels().download<uint32_t>();
    }
};

uint8_t channel(uint32_t word, int c) { return static_cast<uint8_t>(word >> (8 * c)); }

// Radiance spanning the lattice and beyond: log-uniform per channel over 2^-16 .. 2^12, greys,
// black, and saturated primaries.
std::vector<glm::vec4> testRadiance(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> stops(-16.0f, 12.0f);
    std::vector<glm::vec4> sums(count);
    for (uint32_t i = 0; i < count; ++i) {
        glm::vec3 rgb(std::exp2(stops(rng)), std::exp2(stops(rng)), std::exp2(stops(rng)));
        if (i % 7 == 0) rgb = glm::vec3(rgb.x);                        // grey
        if (i % 11 == 0) rgb = glm::vec3(rgb.x, 0.0f, 0.0f);           // a primary
        if (i == 0) rgb = glm::vec3(0.0f);
        const float samples = float(1 + i % 5);
        sums[i] = glm::vec4(rgb * samples, samples);
    }
    return sums;
}

TEST_F(DisplayPassTest, PixelsFollowThePngTransform) {
    const std::vector<glm::vec4> sums = testRadiance(kWidth * kHeight, 3);
    for (const auto& [name, view] : viewTransformChoices()) {
        DisplayPass pass(test::gpu(), kWidth, kHeight, displayLattice(view));
        DisplaySettings settings;
        settings.view = view;
        settings.exposureEv = 1.0f;
        const std::vector<uint32_t> pixels = display(pass, sums, nullptr, 1, settings.exposureScale());
        const ImageRgb linear = pass.linearImage();
        int worst = 0, worstAway = 0;  // anywhere; where the exact channel is 16 or more
        uint64_t off = 0, total = 0;
        for (uint32_t i = 0; i < kWidth * kHeight; ++i) {
            const glm::vec3 l(linear.pixels[3 * i], linear.pixels[3 * i + 1], linear.pixels[3 * i + 2]);
            const auto expected = toDisplayBytes(l, settings);
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(channel(pixels[i], c)) - int(expected[c]));
                worst = std::max(worst, d);
                if (expected[c] >= 16) worstAway = std::max(worstAway, d);
                off += d != 0;
                ++total;
            }
            EXPECT_EQ(channel(pixels[i], 3), 255u);
        }
        std::printf("%s: largest difference %d codes (%d where the channel is 16 or more), %.2f %% of channels differ\n",
                    name.c_str(), worst, worstAway, 100.0 * double(off) / double(total));
        // Measured (lavapipe): 1 code everywhere for clamp and aces-fit; for agx 2 codes, and up to
        // 7 in a channel below 16 that AgX clips to black beside a saturated one (a kink inside a
        // lattice cell).
        EXPECT_LE(worstAway, 2) << name;
        EXPECT_LE(worst, 10) << name;
        EXPECT_LE(double(off), 0.05 * double(total)) << name;
    }
}

TEST_F(DisplayPassTest, LinearImageIsTheHostResolvePlusProgressiveEstimates) {
    const std::vector<glm::vec4> sums = testRadiance(kWidth * kHeight, 5);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<gpu::SppmPixel> sppm(kWidth * kHeight);
    for (uint32_t i = 0; i < sppm.size(); ++i) {
        sppm[i].flux = glm::vec3(u(rng), u(rng), u(rng)) * 3.0f;
        sppm[i].radius2 = i % 13 == 0 ? 0.0f : 1e-3f + u(rng) * 1e-2f;  // no radius yet: adds 0
    }
    DisplayPass pass(test::gpu(), kWidth, kHeight, displayLattice(ViewTransform::AgX));
    display(pass, sums, nullptr);
    const ImageRgb plain = pass.linearImage();
    const ImageRgb host = resolveFilm(sums, kWidth, kHeight);
    EXPECT_EQ(plain.pixels, host.pixels);

    const uint32_t passes = 7;
    display(pass, sums, &sppm, passes);
    const ImageRgb withSppm = pass.linearImage();
    ImageRgb expected = host;  // as ProgressivePhotonIntegrator::finish adds it
    for (uint32_t i = 0; i < sppm.size(); ++i) {
        const glm::vec3 l = gpu::sppmRadiance(sppm[i], float(passes));
        for (int c = 0; c < 3; ++c) expected.pixels[3 * i + c] += l[c];
    }
    // lavapipe rounds as the host does; a GPU may contract the estimate's multiply-adds.
    const uint32_t ulps = test::onLavapipe() ? 0 : 8;
    for (size_t i = 0; i < expected.pixels.size(); ++i)
        ASSERT_LE(test::ulpDistance(withSppm.pixels[i], expected.pixels[i]), ulps)
            << "channel " << i << ": " << withSppm.pixels[i] << " vs " << expected.pixels[i];
    EXPECT_NE(withSppm.pixels, plain.pixels);
}

TEST_F(DisplayPassTest, OutlineAndByteOrder) {
    std::vector<glm::vec4> sums(kWidth * kHeight, glm::vec4(0.18f, 0.05f, 0.01f, 1.0f));
    std::vector<uint8_t> mask(kWidth * kHeight, 0);
    for (uint32_t y = 10; y < 20; ++y)
        for (uint32_t x = 20; x < 40; ++x) mask[y * kWidth + x] = 1;
    DisplayPass pass(test::gpu(), kWidth, kHeight, displayLattice(ViewTransform::AgX));
    const std::vector<uint32_t> plain = display(pass, sums);
    pass.setMask(mask);
    const std::vector<uint32_t> outlined = display(pass, sums);
    const uint32_t orange = 255u | (160u << 8) | (0u << 16) | (255u << 24);
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const uint32_t i = y * kWidth + x;
            const bool border = mask[i] && (x == 20 || x == 39 || y == 10 || y == 19);
            EXPECT_EQ(outlined[i], border ? orange : plain[i]) << x << ", " << y;
        }
    EXPECT_NE(plain[0], orange);
    pass.setMask({});
    const std::vector<uint32_t> swapped = display(pass, sums, nullptr, 1, 1.0f, true);
    for (uint32_t i = 0; i < kWidth * kHeight; ++i) {
        EXPECT_EQ(channel(swapped[i], 0), channel(plain[i], 2));
        EXPECT_EQ(channel(swapped[i], 1), channel(plain[i], 1));
        EXPECT_EQ(channel(swapped[i], 2), channel(plain[i], 0));
    }
}

}  // namespace
}  // namespace vkp
