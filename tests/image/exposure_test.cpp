// --exposure auto: the metering rule of image/exposure.h against values worked out by hand, and
// the parsing of --exposure, and the render command's PNG and EXR header.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

// The decoder only reads back what the PNG writer produced; static so that it cannot clash with
// the copy libstb.so exports.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "support/cli_runner.h"
#include "image/exposure.h"
#include "image/exr.h"
#include "util/errors.h"

namespace vkp {
namespace {

ImageRgb greys(const std::vector<float>& values) {
    ImageRgb image = makeImage(uint32_t(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[3 * i + c] = values[i];
    return image;
}

TEST(AutoExposure, AUniformDimImageIsBroughtToMidGrey) {
    // Every pixel 0.01: L = 0.01, EV = log2(0.18 / 0.01) = log2(18).
    const ExposureMeter meter = meterExposure(greys(std::vector<float>(64, 0.01f)));
    EXPECT_NEAR(meter.ev, std::log2(18.0), 1e-5);
    EXPECT_NEAR(meter.logAverage, 0.01, 1e-8);
    EXPECT_EQ(meter.litPixels, 64u);
    EXPECT_EQ(meter.meteredPixels, 64u - 2u * 3u);  // floor(0.05 * 64) = 3 from each end
    // A bright uniform image is brought down: 4.0 -> EV log2(0.18 / 4).
    EXPECT_NEAR(meterExposure(greys(std::vector<float>(10, 4.0f))).ev, std::log2(0.045), 1e-5);
}

TEST(AutoExposure, BlackPixelsAndOutliersDoNotCount) {
    // 20 lit pixels: one far too dark, one far too bright (floor(0.05 * 20) = 1 dropped at each
    // end), 9 at 0.01 and 9 at 0.04: geometric mean 0.02, EV = log2(0.18 / 0.02) = log2(9).
    // Ten black pixels (no environment behind the object) and a NaN are not metered.
    std::vector<float> values(10, 0.0f);
    values.push_back(std::numeric_limits<float>::quiet_NaN());
    values.push_back(1e-6f);
    values.push_back(1e6f);
    for (int i = 0; i < 9; ++i) {
        values.push_back(0.01f);
        values.push_back(0.04f);
    }
    const ExposureMeter meter = meterExposure(greys(values));
    EXPECT_EQ(meter.litPixels, 20u);
    EXPECT_EQ(meter.meteredPixels, 18u);
    EXPECT_NEAR(meter.logAverage, 0.02, 1e-7);
    EXPECT_NEAR(meter.ev, std::log2(9.0), 1e-5);
}

TEST(AutoExposure, TheConstantSkySeenDirectlyIsLeftOut) {
    // A dark subject (0.02) on the default white sky (1, 1, 1): metering everything would make
    // the sky mid grey and the subject darker still; the sky's pixels are the backdrop.
    std::vector<float> values(30, 1.0f);
    for (int i = 0; i < 10; ++i) values.push_back(0.02f);
    values.push_back(0.9999999f);  // a sky pixel whose film sum rounded: still the sky
    const ImageRgb image = greys(values);
    const ExposureMeter backdrop = meterExposure(image, glm::vec3(1.0f));
    EXPECT_EQ(backdrop.backgroundPixels, 31u);
    EXPECT_EQ(backdrop.litPixels, 10u);
    EXPECT_NEAR(backdrop.ev, std::log2(9.0), 1e-5);
    // Without the backdrop the sky dominates: 41 lit pixels, 2 trimmed at each end.
    const ExposureMeter all = meterExposure(image);
    EXPECT_EQ(all.litPixels, 41u);
    EXPECT_LT(all.ev, 0.0f);
    // A sky of another radiance is not this backdrop; an image of nothing but sky meters the sky.
    EXPECT_EQ(meterExposure(image, glm::vec3(0.5f)).backgroundPixels, 0u);
    EXPECT_NEAR(meterExposure(greys(std::vector<float>(8, 2.0f)), glm::vec3(2.0f)).ev, std::log2(0.09), 1e-5);
    EXPECT_EQ(parseExposureBackground("1,0.5,2"), std::optional<glm::vec3>(glm::vec3(1.0f, 0.5f, 2.0f)));
    EXPECT_EQ(parseExposureBackground("1,0.5"), std::nullopt);
    EXPECT_EQ(exposureAttributes(parseExposure("auto", {}), glm::vec3(1.0f)).back(),
              (std::pair<std::string, std::string>{"vkphoton/exposureBackground", "1,1,1"}));
}

TEST(AutoExposure, LuminanceWeighsTheChannelsAsRec709) {
    // Pure green 0.1 has Y = 0.07152; pure blue 0.1 has Y = 0.00722.
    ImageRgb green = makeImage(4, 4), blue = makeImage(4, 4);
    for (size_t i = 0; i < 16; ++i) {
        green.pixels[3 * i + 1] = 0.1f;
        blue.pixels[3 * i + 2] = 0.1f;
    }
    EXPECT_NEAR(meterExposure(green).ev, std::log2(0.18 / 0.07152), 1e-5);
    EXPECT_NEAR(meterExposure(blue).ev, std::log2(0.18 / 0.00722), 1e-5);
}

TEST(AutoExposure, ABlackImageKeepsEvZeroAndTheRangeIsClamped) {
    EXPECT_EQ(meterExposure(greys(std::vector<float>(8, 0.0f))).ev, 0.0f);
    EXPECT_EQ(meterExposure(greys(std::vector<float>(8, 1e-30f))).ev, 64.0f);  // log2(0.18e30) = 97.1
    EXPECT_EQ(meterExposure(greys(std::vector<float>(8, 3e38f))).ev, -64.0f);
}

TEST(AutoExposure, AFixedExposureIsNotMetered) {
    DisplaySettings fixed = parseExposure("2.5", {});
    EXPECT_FALSE(fixed.autoExposure);
    EXPECT_EQ(resolveExposure(fixed, greys({0.01f, 0.02f})).exposureEv, 2.5f);
    DisplaySettings metered = parseExposure("auto", {});
    EXPECT_TRUE(metered.autoExposure);
    EXPECT_NEAR(resolveExposure(metered, greys({0.01f, 0.01f})).exposureEv, std::log2(18.0), 1e-5);
    EXPECT_EQ(exposureAttributes(resolveExposure(fixed, {})),
              (std::vector<std::pair<std::string, std::string>>{{"vkphoton/exposure", "2.5"},
                                                                {"vkphoton/exposureMode", "fixed"}}));
    for (const char* bad : {"", "nan", "inf", "65", "-65", "1e400", "2x", "Auto"})
        EXPECT_THROW(parseExposure(bad, {}), InputError) << bad;
}

}  // namespace
}  // namespace vkp

// ---- The render command end to end --------------------------------------------------------------

namespace vkp {
namespace {

namespace fs = std::filesystem;

std::string exrAttribute(const ExrAttributes& attributes, const std::string& key) {
    for (const auto& [k, v] : attributes)
        if (k == key) return v;
    return "<missing>";
}

// tests/data/good/triangle.gltf ((0,0,0), (1,0,0), (0,1,0), facing +Z) emitting `radiance` with
// a black base colour: a camera that sees only the triangle sees exactly `radiance` everywhere.
fs::path dimTriangle(const fs::path& dir, float radiance) {
    std::ifstream in(fs::path(VKPHOTON_TEST_DATA) / "good" / "triangle.gltf");
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const size_t at = json.find("\"emissiveFactor\"");
    json.replace(at, json.find(']', at) + 1 - at,
                 fmt::format("\"emissiveFactor\": [{0}, {0}, {0}], \"pbrMetallicRoughness\": "
                             "{{\"baseColorFactor\": [0, 0, 0, 1]}}",
                             radiance));
    fs::copy_file(fs::path(VKPHOTON_TEST_DATA) / "good" / "triangle.bin", dir / "triangle.bin",
                  fs::copy_options::overwrite_existing);
    std::ofstream(dir / "dim.gltf") << json;
    return dir / "dim.gltf";
}

std::vector<uint8_t> pngPixels(const fs::path& path) {
    int w = 0, h = 0, n = 0;
    stbi_uc* decoded = stbi_load(path.string().c_str(), &w, &h, &n, 3);
    if (!decoded) return {};
    std::vector<uint8_t> bytes(decoded, decoded + size_t(w) * h * 3);
    stbi_image_free(decoded);
    return bytes;
}

TEST(AutoExposure, TheRenderCommandMetersThePngAndRecordsTheEv) {
    const fs::path dir = test::freshTempDir("exposure", "render");
    // The camera looks straight at the triangle's inside: every pixel is radiance 0.02.
    const std::string common = "render " + dimTriangle(dir, 0.02f).string() +
                               " --env 0 --spp 2 --width 8 --height 8 --look-from 0.25,0.25,0.5 "
                               "--look-at 0.25,0.25,0 --fov 20 ";
    test::RunResult r = test::runVkphoton(common + "-o " + (dir / "auto.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ExrAttributes attributes;
    const ImageRgb image = readExr(dir / "auto.exr", &attributes);
    for (float v : image.pixels) ASSERT_NEAR(v, 0.02f, 1e-6f);  // the EXR stays linear
    EXPECT_EQ(exrAttribute(attributes, "vkphoton/exposureMode"), "auto");
    const float ev = std::stof(exrAttribute(attributes, "vkphoton/exposure"));
    EXPECT_NEAR(ev, std::log2(9.0), 1e-4);  // log2(0.18 / 0.02)
    EXPECT_NE(r.output.find("exposure auto: EV +3.17"), std::string::npos) << r.output;
    // The PNG shows mid grey: what 0.18 becomes through AgX and sRGB.
    const uint8_t midGrey = toDisplayBytes(glm::vec3(0.18f))[0];
    for (uint8_t b : pngPixels(dir / "auto.png")) ASSERT_NEAR(int(b), int(midGrey), 1);
    EXPECT_EQ(pngPixels(dir / "auto.png").size(), 8u * 8u * 3u);

    // A fixed EV is applied as given, whatever the image.
    r = test::runVkphoton(common + "--quiet --exposure 0 -o " + (dir / "fixed.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ImageRgb fixedImage = readExr(dir / "fixed.exr", &attributes);
    EXPECT_EQ(fixedImage.pixels, image.pixels);
    EXPECT_EQ(exrAttribute(attributes, "vkphoton/exposureMode"), "fixed");
    EXPECT_EQ(exrAttribute(attributes, "vkphoton/exposure"), "0");
    const uint8_t dim = toDisplayBytes(glm::vec3(0.02f))[0];
    EXPECT_LT(int(dim) + 40, int(midGrey));
    for (uint8_t b : pngPixels(dir / "fixed.png")) ASSERT_NEAR(int(b), int(dim), 1);
    EXPECT_EQ(r.output.find("exposure auto"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vkp
