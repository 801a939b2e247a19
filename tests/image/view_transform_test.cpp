// The PNG's display transform: each view transform's black, mid grey, monotonicity and exposure,
// and AgX against the LUT Blender ships.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "image/view_transform.h"
#include "util/errors.h"

namespace vkp {
namespace {

constexpr ViewTransform kAll[] = {ViewTransform::Clamp, ViewTransform::AcesFit, ViewTransform::AgX};

glm::vec3 grey(float v) { return glm::vec3(v); }

TEST(ViewTransform, NamesRoundTrip) {
    ASSERT_EQ(viewTransformChoices().size(), 3u);
    for (const auto& [name, view] : viewTransformChoices()) EXPECT_EQ(viewTransformName(view), name);
    EXPECT_EQ(viewTransformName(DisplaySettings().view), "agx");  // the default
}

TEST(ViewTransform, BlackStaysBlack) {
    for (const ViewTransform view : kAll) {
        // AgX's sigmoid reaches 0 at its toe's limit; in floating point that is 1e-14, as in the LUT.
        const glm::vec3 black = applyViewTransform(grey(0.0f), view);
        if (view == ViewTransform::AgX) EXPECT_LT(glm::max(black.x, glm::max(black.y, black.z)), 1e-12f);
        else EXPECT_EQ(black, grey(0.0f)) << viewTransformName(view);
        for (const float ev : {-10.0f, 0.0f, 10.0f})
            EXPECT_EQ(toDisplayBytes(grey(0.0f), {view, ev}), (std::array<uint8_t, 3>{0, 0, 0})) << viewTransformName(view);
        // Nothing visible below the darkest code value either.
        EXPECT_EQ(toDisplayBytes(grey(1e-6f), {view, 0.0f})[1], 0) << viewTransformName(view);
    }
}

TEST(ViewTransform, NanIsBlackInfinityIsWhite) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const ViewTransform view : kAll) {
        EXPECT_EQ(toDisplayBytes(grey(nan), {view, 0.0f}), (std::array<uint8_t, 3>{0, 0, 0})) << viewTransformName(view);
        EXPECT_EQ(toDisplayBytes(grey(inf), {view, 0.0f}), (std::array<uint8_t, 3>{255, 255, 255})) << viewTransformName(view);
        EXPECT_EQ(toDisplayBytes(grey(-1.0f), {view, 0.0f}), (std::array<uint8_t, 3>{0, 0, 0})) << viewTransformName(view);
        // One bad channel does not poison the others.
        const std::array<uint8_t, 3> mixed = toDisplayBytes(glm::vec3(nan, 0.18f, inf), {view, 0.0f});
        EXPECT_GT(mixed[1], 0) << viewTransformName(view);
        EXPECT_GT(mixed[2], 0) << viewTransformName(view);
    }
}

// Where each curve's definition puts mid grey (0.18 scene-linear).
TEST(ViewTransform, MidGreyLandsWhereTheCurveSaysItDoes) {
    EXPECT_EQ(applyViewTransform(grey(0.18f), ViewTransform::Clamp), grey(0.18f));
    const float aces = 0.18f * (2.51f * 0.18f + 0.03f) / (0.18f * (2.43f * 0.18f + 0.59f) + 0.14f);  // 0.2669
    EXPECT_NEAR(applyViewTransform(grey(0.18f), ViewTransform::AcesFit).y, aces, 1e-6f);
    // AgX's sigmoid passes through (mid grey's place in -10..+6.5 stops, 0.18^(1/2.4)) in the
    // 2.4-power encoding its LUT outputs: display-linear 0.18.
    const glm::vec3 agx = applyViewTransform(grey(0.18f), ViewTransform::AgX);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(agx[c], 0.18f, 2e-6f) << c;
    EXPECT_EQ(linearToSrgb8(0.18f), 118);
    EXPECT_EQ(toDisplayBytes(grey(0.18f), {ViewTransform::Clamp, 0.0f})[1], 118);
    EXPECT_EQ(toDisplayBytes(grey(0.18f), {ViewTransform::AgX, 0.0f})[1], 118);
    EXPECT_EQ(toDisplayBytes(grey(0.18f), {ViewTransform::AcesFit, 0.0f})[1], linearToSrgb8(aces));
}

TEST(ViewTransform, GreyRampsAreMonotonicAndBounded) {
    for (const ViewTransform view : kAll) {
        float previous = 0.0f;
        uint8_t previousByte = 0;
        for (float x = 1e-7f; x < 1e9f; x *= 1.02f) {  // log-spaced: far below black to far above white
            const glm::vec3 y = applyViewTransform(grey(x), view);
            ASSERT_GE(y.y, previous) << viewTransformName(view) << " at " << x;
            ASSERT_LE(y.y, 1.0f) << viewTransformName(view) << " at " << x;
            ASSERT_NEAR(y.x, y.y, 1e-5f) << viewTransformName(view) << ": grey stays grey at " << x;
            ASSERT_NEAR(y.z, y.y, 1e-5f) << viewTransformName(view) << ": grey stays grey at " << x;
            const uint8_t b = toDisplayBytes(grey(x), {view, 0.0f})[1];
            ASSERT_GE(b, previousByte) << viewTransformName(view) << " at " << x;
            previous = y.y;
            previousByte = b;
        }
        EXPECT_EQ(previousByte, 255) << viewTransformName(view);
    }
}

// Brightening a colour never darkens it. (AgX's guard rails and hue mixing can lower a minor
// channel by a few 1e-7 near black, so luminance is what is compared.)
TEST(ViewTransform, ColourRampsAreMonotonic) {
    const auto luminance = [](glm::vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; };
    for (const ViewTransform view : kAll)
        for (const glm::vec3 colour : {glm::vec3(1.0f, 0.1f, 0.02f), glm::vec3(0.05f, 0.3f, 1.0f), glm::vec3(0.2f, 1.0f, 0.4f)}) {
            float previous = 0.0f;
            for (float x = 1e-4f; x < 1e5f; x *= 1.05f) {
                const float y = luminance(applyViewTransform(colour * x, view));
                ASSERT_GE(y, previous - 1e-7f) << viewTransformName(view) << " at " << x;
                previous = y;
            }
            EXPECT_GT(previous, 0.9f) << viewTransformName(view);  // bright enough ends near white
        }
}

TEST(ViewTransform, OneMoreStopIsTwiceTheRadiance) {
    for (const ViewTransform view : kAll)
        for (const float ev : {-3.0f, -0.5f, 0.0f, 0.25f, 2.0f})
            for (float x = 1e-4f; x < 1e4f; x *= 1.37f)
                for (const glm::vec3 c : {grey(x), glm::vec3(x, 0.3f * x, 0.05f * x)})
                    ASSERT_EQ(toDisplayBytes(c, {view, ev + 1.0f}), toDisplayBytes(2.0f * c, {view, ev}))
                        << viewTransformName(view) << " EV " << ev << " x " << x;
    const auto scale = [](float ev) { return DisplaySettings{ViewTransform::Clamp, ev}.exposureScale(); };
    EXPECT_EQ(scale(0.0f), 1.0f);
    EXPECT_EQ(scale(3.0f), 8.0f);
    EXPECT_EQ(scale(-1.0f), 0.5f);
    EXPECT_FLOAT_EQ(scale(0.5f), std::sqrt(2.0f));
    EXPECT_EQ(scale(1.5f), 2.0f * scale(0.5f));
}

TEST(ViewTransform, ExposureOutsideItsRangeIsRefused) {
    for (const float ev : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 65.0f, -65.0f})
        EXPECT_THROW((DisplaySettings{ViewTransform::AgX, ev}.check()), InputError) << ev;
    EXPECT_NO_THROW((DisplaySettings{ViewTransform::AgX, -64.0f}.check()));
}

// Entries of Blender's AgX_Base_sRGB.cube (blender/blender, release/datafiles/colormanagement/
// luts/, 37^3, "40% per-channel shifts"; entry (r, g, b) on line r + 37 g + 1369 b after the
// header): input E-Gamut log2 i/36 over -10..+15 stops, output Rec.709 in a 1/2.4 power.
struct LutEntry {
    int r, g, b;
    glm::dvec3 value;
    double tolerance;
};

// Greys (the diagonal) are the sigmoid alone and agree to the LUT's 7 printed decimals. Colours
// come from the same published generator scripts (EaryChow/AgX_LUT_Gen, 2023-09), which do not
// reproduce the shipped LUT exactly: within 2e-3 for mild colours, 0.014 for a saturated Rec.709
// red (18, 14, 14), up to 0.035 outside Rec.709 at the edge of E-Gamut (the hue-mixing step
// differs somewhat; the tolerances record by how much).
const LutEntry kBlenderLut[] = {
    {0, 0, 0, {0.0000005, 0.0000000, 0.0000018}, 1e-6},
    {14, 14, 14, {0.4495405, 0.4495389, 0.4495729}, 2e-7},
    {36, 36, 36, {1.1271534, 1.1271533, 1.1271549}, 2e-7},
    {15, 14, 14, {0.6120423, 0.4375249, 0.4351344}, 1e-3},
    {14, 15, 14, {0.3797473, 0.5651429, 0.4227875}, 2e-3},
    {15, 15, 14, {0.5673147, 0.5540170, 0.4084009}, 3e-4},
    {16, 16, 14, {0.6690105, 0.6474533, 0.3592662}, 5e-4},
    {20, 19, 14, {0.9499523, 0.8273903, 0.5903412}, 3e-3},
    {16, 15, 14, {0.7131443, 0.5395545, 0.3949447}, 6e-3},
    {18, 14, 14, {0.9384501, 0.4576379, 0.4081734}, 0.015},
    {14, 21, 14, {0.5086458, 0.9710033, 0.5678122}, 0.025},
    {1, 0, 0, {0.0081573, 0.0011301, 0.0000000}, 2e-3},
    {18, 0, 0, {0.9525446, 0.3650527, 0.2597600}, 0.035},
    {10, 5, 0, {0.2058778, 0.0781276, 0.0000000}, 0.015},
    {9, 10, 0, {0.1586622, 0.1905713, 0.0000000}, 7e-3},
    {36, 0, 0, {1.1461240, 1.0997997, 1.0967309}, 1e-4},
};

TEST(AgX, MatchesBlendersLut) {
    for (const LutEntry& e : kBlenderLut) {
        const glm::dvec3 v = agxBaseSrgbLut(glm::dvec3(e.r, e.g, e.b) / 36.0);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(v[c], e.value[c], e.tolerance) << "entry (" << e.r << ", " << e.g << ", " << e.b << ") channel " << c;
    }
}

// The grey ramp in display terms: scene-linear grey -> display-linear, from the sigmoid.
TEST(AgX, GreyRamp) {
    struct Point {
        float scene, display;
    };
    // display = max(0, sigmoid((log2(x / 0.18) + 10) / 16.5))^2.4, evaluated independently here.
    const auto reference = [](double x) {
        const double px = 10.0 / 16.5, py = std::pow(0.18, 1.0 / 2.4), s = 2.4, p = 1.5;
        const auto scale = [&](double dx, double dy) {
            return std::pow(std::pow(s * dx, -p) * (std::pow(s * dx / dy, p) - 1.0), -1.0 / p);
        };
        const double t = (std::log2(x / 0.18) + 10.0) / 16.5;
        const double k = t < px ? scale(px, py) : scale(1.0 - px, 1.0 - py);
        const double u = s * std::abs(t - px) / k;
        const double y = py + (t < px ? -1.0 : 1.0) * k * u / std::pow(1.0 + std::pow(u, p), 1.0 / p);
        return std::pow(std::max(y, 0.0), 2.4);
    };
    for (float x = 0.18f / 1000.0f; x < 0.18f * 30000.0f; x *= 1.5f)
        EXPECT_NEAR(agxDisplayLinear(grey(x)).y, reference(x), 2e-6 * std::max(1.0, reference(x))) << x;
    // Below -10 stops (the LUT's floor) everything is black; above +15 stops it saturates.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(agxDisplayLinear(grey(0.18f / 2048.0f))[c], agxDisplayLinear(grey(0.18f / 1024.0f))[c], 1e-12f);
        EXPECT_NEAR(agxDisplayLinear(grey(0.18f * 65536.0f))[c], agxDisplayLinear(grey(0.18f * 32768.0f))[c], 1e-5f);
    }
    EXPECT_NEAR(agxDisplayLinear(grey(0.18f / 1024.0f)).y, 0.0f, 1e-12f);
}

TEST(AcesFit, KnownValues) {
    EXPECT_EQ(tonemapAces(0.0f), 0.0f);
    EXPECT_NEAR(tonemapAces(1.0f), 2.54f / 3.16f, 1e-6f);  // (2.51 + 0.03) / (2.43 + 0.59 + 0.14)
    EXPECT_EQ(tonemapAces(8.0f), 1.0f);                    // past the crossing of 1 near 7.24
    EXPECT_EQ(tonemapAces(1.0e30f), 1.0f);
    EXPECT_EQ(tonemapAces(INFINITY), 1.0f);
    EXPECT_EQ(tonemapAces(-1.0f), 0.0f);
    EXPECT_EQ(tonemapAces(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(Srgb, KnownValues) {
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_EQ(linearToSrgb(1.0f), 1.0f);
    EXPECT_EQ(linearToSrgb8(0.0f), 0);
    EXPECT_EQ(linearToSrgb8(1.0f), 255);
    EXPECT_EQ(linearToSrgb8(2.0f), 255);
    EXPECT_EQ(linearToSrgb8(-1.0f), 0);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    // Both branches meet at 0.0031308 (0.04045 in sRGB).
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045f, 1e-6f);
    EXPECT_NEAR(linearToSrgb(std::nextafter(0.0031308f, 0.0f)), 0.04045f, 1e-6f);
    EXPECT_NEAR(linearToSrgb(std::nextafter(0.0031308f, 1.0f)), 0.04045f, 1e-6f);
    EXPECT_EQ(linearToSrgb8(0.0031308f), 10);         // 255 * 0.04045 = 10.31
    EXPECT_FLOAT_EQ(linearToSrgb(0.001f), 0.01292f);  // the linear segment
    EXPECT_NEAR(linearToSrgb(0.5f), 0.7353569f, 1e-6f);
    EXPECT_EQ(linearToSrgb8(0.5f), 188);
}

}  // namespace
}  // namespace vkp
